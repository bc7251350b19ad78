#include "input.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sw {

bool encode_nonfinite(Json& root) {
  bool any = false;
  std::vector<Json*> todo{&root};  // no recursion: results may be deep
  while (!todo.empty()) {
    Json* j = todo.back();
    todo.pop_back();
    if (j->is_number_float() && !std::isfinite(j->get<double>())) {
      const double d = j->get<double>();
      *j = std::isnan(d) ? "NaN" : d > 0 ? "Infinity" : "-Infinity";
      any = true;
    } else if (j->is_structured()) {
      for (Json& c : *j) todo.push_back(&c);
    }
  }
  return any;
}

bool is_nonfinite_text(std::string_view s) { return s == "NaN" || s == "Infinity" || s == "-Infinity"; }

void check_json_text(std::string_view text, std::string_view what) {
  const std::string w(what);
  if (text.size() > kMaxJsonBytes) throw InputError(w + ": " + std::to_string(text.size()) + " bytes of JSON, more than the " + std::to_string(kMaxJsonBytes >> 20) + " MiB allowed");
  std::size_t depth = 0;
  bool in_string = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\0') throw InputError(w + ": a NUL byte at offset " + std::to_string(i));
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) throw InputError(w + ": nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

InputError json_text_error(const Json::exception& e, std::string_view what) {
  if (e.id / 100 == 4) return InputError(std::string(what) + ": a number overflows double (write large or exact values as \"p/q\" strings)");
  // Keep nlohmann's position and reason, drop its "[json.exception...]" prefix.
  std::string why = e.what();
  const auto at = why.find("parse error");
  why = at == std::string::npos ? why : why.substr(at);
  return InputError(std::string(what) + ": malformed JSON (" + why + ")");
}

void refuse_duplicate_key(std::vector<std::string>& keys, std::string_view what) {
  std::sort(keys.begin(), keys.end());
  const auto dup = std::adjacent_find(keys.begin(), keys.end());
  if (dup != keys.end()) throw InputError(std::string(what) + ": duplicate key \"" + one_line(*dup, 200) + "\"");
}

Json parse_json_text(std::string_view text, std::string_view what) {
  // Before the parser: the size, a NUL byte (which would end the text early) and the nesting depth.
  check_json_text(text, what);
  // The parser itself: duplicate keys are refused, not silently merged. An object with a duplicate
  // ends with fewer members than keys were read (the parser keeps the last): keys are only counted,
  // and only then is the text read again with its keys kept and sorted to name the duplicate. So
  // the check is linear in the keys and allocates nothing (check parses every trace line).
  struct Duplicate {};
  std::vector<std::size_t> counts;
  auto counted = [&](int, Json::parse_event_t event, Json& parsed) {
    if (event == Json::parse_event_t::object_start) counts.push_back(0);
    else if (event == Json::parse_event_t::key && !counts.empty()) ++counts.back();
    else if (event == Json::parse_event_t::object_end && !counts.empty()) {
      if (parsed.is_object() && parsed.size() != counts.back()) throw Duplicate{};
      counts.pop_back();
    }
    return true;
  };
  std::vector<std::vector<std::string>> keys;
  auto named = [&](int, Json::parse_event_t event, Json& parsed) {
    if (event == Json::parse_event_t::object_start) {
      keys.emplace_back();
    } else if (event == Json::parse_event_t::key && !keys.empty()) {
      keys.back().push_back(parsed.get<std::string>());
    } else if (event == Json::parse_event_t::object_end && !keys.empty()) {
      if (parsed.is_object() && parsed.size() != keys.back().size()) refuse_duplicate_key(keys.back(), what);
      keys.pop_back();
    }
    return true;
  };
  auto strict = [&](int depth, Json::parse_event_t event, Json& parsed) -> bool {
    try {
      return counted(depth, event, parsed);
    } catch (const Duplicate&) {
      const Json again = Json::parse(text.begin(), text.end(), named);
      (void)again;
      throw InputError(std::string(what) + ": duplicate key");  // not reached: the second reading names it
    }
  };
  try {
    return Json::parse(text.begin(), text.end(), strict);
  } catch (const Json::parse_error& e) {
    throw json_text_error(e, what);
  } catch (const Json::out_of_range& e) {
    throw json_text_error(e, what);
  }
}

bool read_line(std::istream& in, std::string& line, std::size_t max, const std::string& what) {
  line.clear();
  char buf[1 << 16];
  bool any = false;
  for (;;) {
    in.getline(buf, sizeof buf);
    const std::streamsize n = in.gcount();  // counts the '\n' when it was read (not stored)
    const bool at_end = in.eof(), full = !at_end && in.fail();  // full: the line goes on
    line.append(buf, static_cast<std::size_t>(full || at_end ? n : n - 1));
    any = any || n > 0;
    if (line.size() > max) throw InputError(what + ": a line of more than " + std::to_string(max) + " bytes");
    if (!full) return any;
    in.clear();
  }
}

void require_regular_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (st.type() != std::filesystem::file_type::regular && st.type() != std::filesystem::file_type::not_found) throw InputError(what + ": '" + one_line(path, 200) + "' is not a regular file");
}

std::ifstream open_input_file(const std::string& path, std::string_view what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(std::string(what) + " '" + path + "' is a directory");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError("cannot read " + std::string(what) + " '" + path + "'");
  return f;
}

Json read_input_arg(const std::string& arg) {
  const auto first = arg.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && (arg[first] == '{' || arg[first] == '[')) return parse_json_text(arg, "input");
  return parse_json_text(read_file_bounded(arg, "input file", kMaxJsonBytes), "input file '" + arg + "'");
}

std::string read_file_bounded(const std::string& path, std::string_view what, std::size_t max) {
  std::ifstream f = open_input_file(path, what);
  std::string text;
  char buf[1 << 16];
  while (f.read(buf, sizeof buf) || f.gcount() > 0) {  // a FIFO or a device has no size: read in blocks, bounded
    text.append(buf, static_cast<std::size_t>(f.gcount()));
    if (text.size() > max) throw InputError(std::string(what) + " '" + one_line(path, 200) + "': more than " + std::to_string(max >> 10) + " KiB");
  }
  return text;
}

std::string one_line(std::string_view message, std::size_t max) {
  std::string out;
  for (unsigned char c : message) {
    if (out.size() >= max) {
      out += "...";
      break;
    }
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c == '\r') out += "\\r";
    else if (c < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

static Rational parse_decimal_or_fraction(const std::string& s, const std::string& what, std::size_t max_chars) {
  auto bad = [&] { return InputError(what + ": '" + one_line(s, 60) + "' is not a number or an exact \"p/q\""); };
  if (s.size() > max_chars)
    throw InputError(what + ": an exact number of " + std::to_string(s.size()) + " characters, more than the " + std::to_string(max_chars) +
                     (max_chars == kMaxInputNumberChars ? " an input's numbers may have" : " a trace's numbers may have"));
  if (s.empty()) throw bad();
  const auto slash = s.find('/');
  auto digits_ok = [](std::string_view t, bool allow_point) {
    std::size_t i = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
    bool any = false, point = false;
    for (; i < t.size(); ++i) {
      if (t[i] >= '0' && t[i] <= '9') any = true;
      else if (allow_point && t[i] == '.' && !point) point = true;
      else return false;
    }
    return any;
  };
  if (slash != std::string::npos) {
    std::string p = s.substr(0, slash), q = s.substr(slash + 1);
    if (!digits_ok(p, false) || !digits_ok(q, false) || q[0] == '-' || q[0] == '+') throw bad();
    if (p[0] == '+') p = p.substr(1);
    mpz_class den(q, 10);
    if (den == 0) throw InputError(what + ": zero denominator in '" + s + "'");
    Rational r(mpz_class(p, 10), den);
    r.canonicalize();
    return r;
  }
  if (!digits_ok(s, true)) throw bad();
  std::string t = s[0] == '+' ? s.substr(1) : s;
  const auto point = t.find('.');
  if (point == std::string::npos) return Rational(mpz_class(t, 10));
  std::string whole = t.substr(0, point) + t.substr(point + 1);
  if (whole == "-" || whole.empty()) throw bad();
  mpz_class den;
  mpz_ui_pow_ui(den.get_mpz_t(), 10, t.size() - point - 1);
  Rational r(mpz_class(whole, 10), den);
  r.canonicalize();
  return r;
}

Rational parse_rational(const Json& v, const std::string& what, std::size_t max_chars) {
  if (v.is_number_integer()) return v.is_number_unsigned() ? Rational(mpz_class(std::to_string(v.get<std::uint64_t>()), 10)) : Rational(mpz_class(std::to_string(v.get<std::int64_t>()), 10));
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (!std::isfinite(d)) throw InputError(what + ": not a finite number");
    return num::to_rational(d);
  }
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "nan" || s == "NaN" || s == "inf" || s == "-inf" || s == "Infinity" || s == "-Infinity")
      throw InputError(what + ": not a finite number");
    return parse_decimal_or_fraction(s, what, max_chars);
  }
  throw InputError(what + ": expected a number, got " + std::string(v.type_name()));
}

const Json& require(const Json& obj, const char* key, const std::string& what) {
  if (!obj.is_object()) throw InputError(what + ": expected an object");
  auto it = obj.find(key);
  if (it == obj.end()) throw InputError(what + ": missing field \"" + key + "\"");
  return *it;
}

void only_keys_optional(const Json& obj, std::initializer_list<const char*> keys, std::initializer_list<const char*> optional,
                        const std::string& what) {
  if (!obj.is_object()) throw InputError(what + ": expected an object");
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    for (const char* k : optional) known = known || it.key() == k;
    if (!known) throw InputError(what + ": unknown field \"" + one_line(it.key(), 60) + "\"");
  }
  for (const char* k : keys) (void)require(obj, k, what);
}

void only_keys(const Json& obj, std::initializer_list<const char*> keys, const std::string& what) { only_keys_optional(obj, keys, {}, what); }

template <int N> static std::array<Rational, N> parse_array(const Json& obj, const char* key) {
  const Json& a = require(obj, key, "input");
  const std::string what = std::string("input.") + key;
  if (!a.is_array() || a.size() != N)
    throw InputError(what + ": expected an array of " + std::to_string(N) + " numbers");
  std::array<Rational, N> r;
  for (int i = 0; i < N; ++i) r[i] = parse_rational(a[i], what + "[" + std::to_string(i) + "]");
  return r;
}

Vec2<Rational> parse_point2(const Json& obj, const char* key) {
  auto a = parse_array<2>(obj, key);
  return {a[0], a[1]};
}
Vec3<Rational> parse_point3(const Json& obj, const char* key) {
  auto a = parse_array<3>(obj, key);
  return {a[0], a[1], a[2]};
}

std::int64_t parse_integer(const Json& v, const std::string& what, std::int64_t lo, std::int64_t hi) {
  const Rational q = parse_rational(v, what);
  if (q.get_den() != 1) throw InputError(what + ": " + q.get_str() + " is not an integer");
  if (q < Rational(lo) || q > Rational(hi))
    throw InputError(what + ": " + q.get_str() + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return num::int64_of(q.get_num());
}

void check_digits(const Rational& v, const std::string& what) {
  if (mpz_sizeinbase(v.get_num_mpz_t(), 2) > 64 || mpz_sizeinbase(v.get_den_mpz_t(), 2) > 64)
    throw InputError(what + ": numerator or denominator beyond 64 bits");
}

void check_bound(const Rational& v, double bound, const std::string& what) {
  if (abs(v) > Rational(bound))
    throw InputError(what + ": " + v.get_str() + " is beyond the bound " + num::to_text(bound));
}

}  // namespace sw
