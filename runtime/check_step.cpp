// A replayed step against the trace's: the shape a step line must have, the first field that
// differs, and where a student looks for it (check_step.hpp).
#include "check_step.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include "trace_io.hpp"

namespace sw::check_values {

namespace {

// A geometry item is an object with one kind key ({"pixel":[i,j]}) and optional modifiers.
constexpr const char* kItemModifiers[] = {"label", "life", "value"};
bool is_modifier(std::string_view key) {
  for (const char* m : kItemModifiers)
    if (key == m) return true;
  return false;
}
std::string item_kind(const Json& item) {
  for (auto it = item.begin(); it != item.end(); ++it)
    if (!is_modifier(it.key())) return it.key();
  return "";
}

// Line `id` of the listing the replay's step counts in: the algorithm's own, or a nested callee's
// ("in"); nullptr for an id out of range or a scope neither the catalog nor the callees know (its
// lines are then named by number only). Looked up only for a message, not per step.
const ListingLine* listing_line(const Json& want, const Listing& own, std::int64_t id) {
  const std::string in = want.value("in", "");
  const Listing* l = in.empty() ? &own : find_listing(in);
  return l && id >= 1 && id <= static_cast<std::int64_t>(l->lines.size()) ? &l->lines[id - 1] : nullptr;
}

}  // namespace

std::string line_label(const Json& want, const Listing& own) {
  const auto id = want.at("line").get<std::int64_t>();
  std::string s = "line " + std::to_string(id);
  if (want.contains("in")) s += " of " + want["in"].get<std::string>();
  if (const ListingLine* l = listing_line(want, own, id)) {
    s += " (" + std::string(l->name) + ": " + one_line(listing_text(l->text), 120) + ")";
  }
  return s;
}

namespace {

// A variable's value for a message: a scalar as show() gives it, a vector as (x, y).
std::string brief(const Json& v) {
  const Json& parts = v.is_object() && v.contains("rgb") ? v["rgb"] : v;
  if (!parts.is_array()) return show(parts);
  std::string t = v.is_object() ? "rgb(" : "(";
  for (std::size_t k = 0; k < parts.size() && k < 8; ++k) t += (k ? ", " : "") + show(parts[k]);
  return t + (parts.size() > 8 ? ", ...)" : ")");
}

}  // namespace

std::string step_context(const std::string& want_text, const std::string& got_text, std::size_t index, const Listing& own, const Tolerance& tol) {
  const Json want = Json::parse(want_text);
  const Json got = Json::parse(got_text, nullptr, false);
  std::string s = "after step " + std::to_string(index) + " at " + line_label(want, own) + ":";
  const Json& vars = want.at("vars");
  if (vars.empty()) return s + " no variables";
  std::size_t shown = 0;
  for (auto it = vars.begin(); it != vars.end(); ++it) {
    if (++shown > 8) return s + " ...";
    s += (shown > 1 ? ", " : " ") + it.key() + " = " + brief(*it);
    if (!got.is_object() || !got.contains("vars") || !got["vars"].is_object() || !got["vars"].contains(it.key())) continue;
    const Json& mine = got["vars"][it.key()];
    if (value_diff(*it, mine, Tolerance{tol.rel}, it->is_number_integer(), it.key())) s += " (trace: " + brief(mine) + ")";
  }
  return s;
}

std::optional<std::string> step_diff(const Json& want, const Json& got, const Tolerance& tol, const Listing& listing) {
  // Steps inside a nested call name the callee ("in") and count lines in its listing.
  const std::string want_in = want.value("in", ""), got_in = got.contains("in") && got["in"].is_string() ? got["in"].get<std::string>() : "";
  if (want_in != got_in)
    return "listing: expected a step of " + (want_in.empty() ? std::string("the algorithm itself") : want_in) + ", got one of " + (got_in.empty() ? std::string("the algorithm itself") : got_in);
  // Lines are named only in a message: the callee's listing is looked up then, not per step.
  auto line_name = [&](const Json& l) {
    const ListingLine* line = listing_line(want, listing, l.get<std::int64_t>());
    return l.dump() + (line ? " (" + std::string(line->name) + ")" : "");
  };
  if (got.at("line") != want.at("line")) return "line: expected " + line_name(want.at("line")) + ", got " + line_name(got.at("line"));
  if (got.at("kind") != want.at("kind")) return "kind: expected " + want.at("kind").dump() + ", got " + got.at("kind").dump();
  const Json& wv = want.at("vars");
  const Json& gv = got.at("vars");
  for (auto it = wv.begin(); it != wv.end(); ++it) {
    if (!gv.contains(it.key())) return "variable " + it.key() + ": missing";
    // The replay writes integers bare and numbers as strings; an integer list is compared as integers.
    const bool is_int = it->is_number_integer() || (it->is_array() && !it->empty() && std::all_of(it->begin(), it->end(), [](const Json& x) { return x.is_number_integer(); }));
    if (!tol.numbers && !is_int) continue;
    if (auto d = value_diff(*it, gv[it.key()], tol, is_int, "variable " + it.key())) return d;
  }
  for (auto it = gv.begin(); it != gv.end(); ++it)
    if (!wv.contains(it.key())) return "variable " + it.key() + ": not recorded by the algorithm at this step";
  if (!got.contains("geo")) return std::nullopt;  // left out, as --decisions-only allows
  const Json& wg = want.at("geo");
  const Json& gg = got.at("geo");
  if (wg.size() != gg.size()) return "geo: expected " + std::to_string(wg.size()) + " items, got " + std::to_string(gg.size());
  for (std::size_t k = 0; k < wg.size(); ++k) {
    const std::string name = item_kind(wg[k]);
    const std::string path = "geo[" + std::to_string(k) + "]." + name;
    if (!gg[k].is_object() || !gg[k].contains(name)) return path + ": expected a \"" + name + "\" item, got " + show(gg[k]);
    const auto kind = parse_geo(name);
    const bool decision = kind && geo_desc(*kind).decision;  // the vocabulary's rule
    if (tol.numbers || decision)
      if (auto d = value_diff(wg[k][name], gg[k][name], tol, decision, path)) return d;
    // Label, lifetime and value are the trace's to state or leave out (a hand-written trace need
    // not label its geometry); stated, they must match.
    for (const char* key : kItemModifiers) {
      if (!gg[k].contains(key)) continue;
      const std::string at = "geo[" + std::to_string(k) + "]." + key;
      if (!wg[k].contains(key)) return at + ": not recorded by the algorithm";
      if (std::string_view(key) != "value") {
        if (wg[k][key] != gg[k][key]) return at + ": expected " + wg[k][key].dump() + ", got " + gg[k][key].dump();
      } else if (tol.numbers) {
        if (auto d = value_diff(wg[k][key], gg[k][key], tol, false, at)) return d;
      }
    }
  }
  return std::nullopt;
}

// Stated, "geo" is read and compared even when geometry is false.
void require_step_shape(const Json& j, std::size_t lineno, bool geometry) {
  auto bad = [&](const char* why) { throw InputError("line " + std::to_string(lineno) + ": " + why); };
  if (!j.is_object()) bad("expected a step object");
  if (!j.contains("line") || !j["line"].is_number_integer()) bad("step without an integer \"line\"");
  if (!j.contains("kind") || !j["kind"].is_string()) bad("step without a string \"kind\"");
  if (!j.contains("vars") || !j["vars"].is_object()) bad("step without a \"vars\" object");
  if ((geometry || j.contains("geo")) && (!j.contains("geo") || !j["geo"].is_array())) bad("step without a \"geo\" array");
  static const Json kNoGeometry = Json::array();
  for (const Json& item : j.contains("geo") ? j["geo"] : kNoGeometry) {
    if (!item.is_object()) bad("a geometry item that is not an object");
    std::size_t kinds = 0;
    for (auto it = item.begin(); it != item.end(); ++it) {
      if (!is_modifier(it.key())) ++kinds;
      else if (it.key() == "value") {
        if (!(it->is_string() && is_nonfinite_text(it->get<std::string>()))) (void)parse_rational(*it, "line " + std::to_string(lineno) + ": geometry value", kMaxExactTextChars);
      }
      else if (!it->is_string() || (it.key() == "life" && !parse_life(it->get<std::string>()))) bad("a geometry label or life that is not one of its strings");
    }
    if (kinds != 1) bad("a geometry item with other than one kind key");
  }
  // A variable is a number, a "p/q" string, a list of up to kMaxListLength of them (a vector is a list
  // of 2 or 3), or a colour {"rgb": [r, g, b]}.
  auto number = [&](const Json& v, const std::string& what) {
    if (!v.is_number() && !v.is_string()) bad("a variable that is neither a number, a \"p/q\" string nor a vector of them");
    if (v.is_string() && !is_nonfinite_text(v.get<std::string>())) (void)parse_rational(v, "line " + std::to_string(lineno) + ": " + what, kMaxExactTextChars);
  };
  for (auto it = j["vars"].begin(); it != j["vars"].end(); ++it) {
    const Json* list = &*it;
    if (it->is_object()) {
      if (it->size() != 1 || !it->contains("rgb") || !(*it)["rgb"].is_array() || (*it)["rgb"].size() != 3) bad("an object variable other than a colour {\"rgb\": [r, g, b]}");
      list = &(*it)["rgb"];
    }
    if (!list->is_array()) {
      number(*list, "vars." + it.key());
      continue;
    }
    if (list->size() > kMaxListLength) bad("a list variable of more than 64 entries");
    for (const Json& c : *list) number(c, "vars." + it.key());
  }
}

}  // namespace sw::check_values
