// Reading inputs: JSON numbers or exact "p/q" strings, checked for finiteness and bounds. Every
// failure throws InputError with one line that names the problem.
#pragma once
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw {

using Json = nlohmann::json;

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// JSON has no token for NaN or the infinities: results and traces write them as the strings "NaN",
// "Infinity" and "-Infinity" (docs/trace-format.md), and readers of traces accept those.
// Returns whether it replaced any.
bool encode_nonfinite(Json& j);
bool is_nonfinite_text(std::string_view s);

// The readers' bounds (docs/cli.md), checked before any work: JSON text of at most kMaxJsonBytes,
// nested at most kMaxJsonDepth deep, with no NUL byte, no duplicate key and no number beyond double.
inline constexpr std::size_t kMaxJsonBytes = std::size_t{64} << 20;
inline constexpr std::size_t kMaxJsonDepth = 64;

// Parses JSON text within those bounds; anything else throws InputError naming `what`.
Json parse_json_text(std::string_view text, std::string_view what);
// What parse_json_text holds a text to before parsing it: its size, no NUL byte, its nesting.
void check_json_text(std::string_view text, std::string_view what);
// The line parse_json_text gives for a parser's error: nlohmann's position and reason, or a number
// that overflows double.
InputError json_text_error(const Json::exception& e, std::string_view what);
// Throws the line parse_json_text gives for a duplicate key if an object's `keys` (sorted here)
// hold one: the first in sorted order.
void refuse_duplicate_key(std::vector<std::string>& keys, std::string_view what);
// An --input argument: JSON text (starting with '{' or '[') or the name of a file holding it.
Json read_input_arg(const std::string& arg);
// std::getline with a bound: reads the next line (without its '\n') into `line`, false at the end.
// A line of more than `max` bytes throws InputError naming `what`, before more of it is read.
bool read_line(std::istream& in, std::string& line, std::size_t max, const std::string& what);
// A file named inside data (a mesh, a texture, a scene) must be a regular file: a FIFO or a device
// there would hang the reader. Throws InputError naming `what` if it exists and is not one (a
// missing file is the reader's to report).
void require_regular_file(const std::string& path, const std::string& what);
// Opens a file to read, or throws InputError naming `what`: missing, unreadable, a directory.
std::ifstream open_input_file(const std::string& path, std::string_view what);
// The whole file (or FIFO or device), read in blocks; throws InputError naming `what` past max bytes.
std::string read_file_bounded(const std::string& path, std::string_view what, std::size_t max);
// A message as one line for a terminal: control characters escaped (\n, \t, \xNN), cut to about
// `max` bytes with "..." (echoed input may be a megabyte long; echo points cut it shorter).
std::string one_line(std::string_view message, std::size_t max = 1000);
// Exact numbers as strings ("p/q", "-1.25"): at most kMaxInputNumberChars characters in an input;
// in a trace (the values a run records) at most kMaxExactTextChars (core/number.hpp): `trace`
// refuses to write a longer one and `check` reads up to it (docs/trace-format.md).
inline constexpr std::size_t kMaxInputNumberChars = 4096;
// A number (finite) or a string "n", "p/q" or a decimal like "-1.25" of at most max_chars
// characters; `what` names it in errors.
Rational parse_rational(const Json& v, const std::string& what, std::size_t max_chars = kMaxInputNumberChars);
// obj is an object with exactly these fields: throws "unknown field" or "missing field".
void only_keys(const Json& obj, std::initializer_list<const char*> keys, const std::string& what);
// The same, where the `optional` fields may also appear.
void only_keys_optional(const Json& obj, std::initializer_list<const char*> keys, std::initializer_list<const char*> optional,
                        const std::string& what);
// obj[key] must exist; throws "missing field" otherwise.
const Json& require(const Json& obj, const char* key, const std::string& what);
Vec2<Rational> parse_point2(const Json& obj, const char* key);
Vec3<Rational> parse_point3(const Json& obj, const char* key);
// An integer in [lo, hi] (a JSON integer, an integral number or an exact string such as "7").
std::int64_t parse_integer(const Json& v, const std::string& what, std::int64_t lo, std::int64_t hi);
// Throws unless v's numerator and denominator have at most 64 bits each: the curves' bound on
// exact input, which keeps exact arithmetic on long walks fast.
void check_digits(const Rational& v, const std::string& what);
// Throws unless |v| <= bound.
void check_bound(const Rational& v, double bound, const std::string& what);

template <class Num> Vec2<Num> to_num(const Vec2<Rational>& p) {
  return {num::from_rational<Num>(p.x), num::from_rational<Num>(p.y)};
}
template <class Num> Vec3<Num> to_num(const Vec3<Rational>& p) {
  return {num::from_rational<Num>(p.x), num::from_rational<Num>(p.y), num::from_rational<Num>(p.z)};
}

}  // namespace sw
