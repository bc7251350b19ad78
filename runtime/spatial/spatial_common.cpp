#include "spatial/spatial_common.hpp"
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include "spatial_oracle.hpp"

namespace sw::spatial {

double parse_coord(const Json& v, const std::string& what) {
  const Rational q = parse_rational(v, what);
  check_bound(q, kCoordBound, what);
  const double d = q.get_d();
  if (num::to_rational(d) != q) throw InputError(what + ": " + q.get_str() + " is not a double (spatial inputs are doubles)");
  // Keep a JSON -0.0 (a ray direction's sign of zero matters to the slab test).
  return v.is_number_float() ? v.get<double>() : d;
}

template <int D> std::array<double, D> parse_vec(const Json& v, const std::string& what) {
  if (!v.is_array() || v.size() != D) throw InputError(what + ": expected an array of " + std::to_string(D) + " numbers");
  std::array<double, D> out;
  for (int k = 0; k < D; ++k) out[k] = parse_coord(v[k], what + "[" + std::to_string(k) + "]");
  return out;
}
template std::array<double, 2> parse_vec<2>(const Json&, const std::string&);
template std::array<double, 3> parse_vec<3>(const Json&, const std::string&);

Mesh parse_mesh(const Json& in, const std::string& what) {
  const bool inline_tris = in.contains("triangles"), file = in.contains("mesh");
  if (inline_tris == file) throw InputError(what + ": expected exactly one of \"triangles\" and \"mesh\"");
  if (file) {
    if (!in["mesh"].is_string()) throw InputError(what + ".mesh: expected a file name (.off or .obj)");
    return read_mesh_file(in["mesh"].get<std::string>());
  }
  const Json& t = in["triangles"];
  if (!t.is_array() || t.empty()) throw InputError(what + ".triangles: expected a non-empty array of triangles");
  if (t.size() > kMaxTriangles) throw InputError(what + ".triangles: " + std::to_string(t.size()) + " triangles, more than the bound " + std::to_string(kMaxTriangles));
  Mesh m;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const std::string w = what + ".triangles[" + std::to_string(i) + "]";
    if (!t[i].is_array() || t[i].size() != 3) throw InputError(w + ": expected [[x,y,z],[x,y,z],[x,y,z]]");
    const auto base = static_cast<std::int32_t>(m.v.size());
    for (int c = 0; c < 3; ++c) m.v.push_back(parse_vec<3>(t[i][c], w + "[" + std::to_string(c) + "]"));
    m.f.push_back({base, base + 1, base + 2});
  }
  return m;
}

namespace {

// One line of a mesh file, with where it is for errors.
struct LineReader {
  std::ifstream in;
  std::string path, line;
  std::size_t number = 0;
  bool next() {
    while (std::getline(in, line)) {
      ++number;
      if (line.size() > 4096) fail("a line longer than 4096 characters");
      const auto hash = line.find('#');
      if (hash != std::string::npos) line.resize(hash);
      if (line.find_first_not_of(" \t\r") != std::string::npos) return true;
    }
    return false;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(path + (number ? ":" + std::to_string(number) : std::string()) + ": " + why);
  }
  double coord(std::istringstream& s) const {
    std::string tok;
    if (!(s >> tok)) fail("expected a coordinate");
    char* end = nullptr;
    const double d = std::strtod(tok.c_str(), &end);
    if (end != tok.c_str() + tok.size()) fail("'" + tok.substr(0, 32) + "' is not a number");
    if (!std::isfinite(d) || std::fabs(d) > kCoordBound) fail("coordinate " + tok.substr(0, 32) + " is not finite or beyond 1e15");
    return d;
  }
  long integer(std::istringstream& s, const char* what) const {
    long v = 0;
    if (!(s >> v)) fail(std::string("expected ") + what);
    return v;
  }
};

// A polygon's vertex indices (0-based, checked) as a fan of triangles.
void add_polygon(Mesh& m, const std::vector<long>& idx, const LineReader& r) {
  if (idx.size() < 3) r.fail("a face needs at least 3 vertices");
  for (long i : idx)
    if (i < 0 || static_cast<std::size_t>(i) >= m.v.size()) r.fail("vertex index " + std::to_string(i) + " out of range");
  for (std::size_t k = 1; k + 1 < idx.size(); ++k) {
    if (m.f.size() >= kMaxTriangles) r.fail("more than " + std::to_string(kMaxTriangles) + " triangles");
    m.f.push_back({static_cast<std::int32_t>(idx[0]), static_cast<std::int32_t>(idx[k]), static_cast<std::int32_t>(idx[k + 1])});
  }
}

Mesh read_off(LineReader& r) {
  if (!r.next()) r.fail("empty file");
  std::istringstream head(r.line);
  std::string magic;
  head >> magic;
  if (magic != "OFF") r.fail("expected the OFF header");
  std::istringstream counts(r.line.substr(3));
  long nv = -1, nf = -1;
  if (!(counts >> nv)) {  // the counts on a line of their own
    if (!r.next()) r.fail("expected the vertex and face counts");
    counts = std::istringstream(r.line);
    counts >> nv;
  }
  if (!(counts >> nf) || nv < 0 || nf < 0) r.fail("expected the vertex and face counts");
  if (static_cast<std::size_t>(nv) > 3 * kMaxTriangles || static_cast<std::size_t>(nf) > kMaxTriangles)
    r.fail("more than " + std::to_string(kMaxTriangles) + " faces or " + std::to_string(3 * kMaxTriangles) + " vertices");
  Mesh m;
  m.v.reserve(static_cast<std::size_t>(nv));
  for (long i = 0; i < nv; ++i) {
    if (!r.next()) r.fail("the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    std::istringstream s(r.line);
    m.v.push_back({r.coord(s), r.coord(s), r.coord(s)});
  }
  for (long i = 0; i < nf; ++i) {
    if (!r.next()) r.fail("the file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
    std::istringstream s(r.line);
    const long n = r.integer(s, "the face's vertex count");
    if (n < 3 || n > 1024) r.fail("a face of " + std::to_string(n) + " vertices (3 to 1024)");
    std::vector<long> idx;
    for (long k = 0; k < n; ++k) idx.push_back(r.integer(s, "a vertex index"));
    add_polygon(m, idx, r);
  }
  return m;
}

Mesh read_obj(LineReader& r) {
  Mesh m;
  while (r.next()) {
    std::istringstream s(r.line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      if (m.v.size() >= 3 * kMaxTriangles) r.fail("more than " + std::to_string(3 * kMaxTriangles) + " vertices");
      m.v.push_back({r.coord(s), r.coord(s), r.coord(s)});
    } else if (tag == "f") {
      std::vector<long> idx;
      std::string tok;
      while (s >> tok && idx.size() <= 1024) {  // "i", "i/t", "i//n" or "i/t/n"; negative counts back
        char* end = nullptr;
        const long i = std::strtol(tok.c_str(), &end, 10);
        if (end == tok.c_str() || (*end != '\0' && *end != '/') || i == 0) r.fail("'" + tok.substr(0, 32) + "' is not a vertex index");
        idx.push_back(i > 0 ? i - 1 : static_cast<long>(m.v.size()) + i);
      }
      add_polygon(m, idx, r);
    }
    // Other statements (vt, vn, g, o, s, usemtl, mtllib, l, p) carry nothing a tree needs.
  }
  return m;
}

std::atomic<std::uint64_t> g_mesh_files_opened{0};

}  // namespace

std::uint64_t mesh_files_opened() { return g_mesh_files_opened.load(); }

Mesh read_mesh_file(const std::string& path) {
  const std::string shown = path.substr(0, 200);
  LineReader r;
  r.path = shown;
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  if (ext != "off" && ext != "obj") throw InputError(shown + ": expected a .off or .obj mesh file");
  require_regular_file(path, "mesh file");
  r.in.open(path, std::ios::binary | std::ios::ate);
  ++g_mesh_files_opened;
  if (!r.in) throw InputError(shown + ": cannot read the mesh file");
  const auto size = static_cast<std::size_t>(r.in.tellg());
  if (size > kMaxMeshBytes) throw InputError(shown + ": " + std::to_string(size) + " bytes, more than the bound " + std::to_string(kMaxMeshBytes));
  r.in.seekg(0);
  Mesh m = ext == "off" ? read_off(r) : read_obj(r);
  if (r.in.bad()) throw InputError(shown + ": cannot read the mesh file");
  if (m.f.empty()) throw InputError(shown + ": no faces");
  return m;
}

template <int D> std::vector<std::array<double, D>> parse_points(const Json& arr, const std::string& what) {
  if (!arr.is_array() || arr.empty()) throw InputError(what + ": expected a non-empty array of points");
  if (arr.size() > kMaxPoints) throw InputError(what + ": " + std::to_string(arr.size()) + " points, more than the bound " + std::to_string(kMaxPoints));
  std::vector<std::array<double, D>> out;
  out.reserve(arr.size());
  for (std::size_t i = 0; i < arr.size(); ++i) out.push_back(parse_vec<D>(arr[i], what + "[" + std::to_string(i) + "]"));
  return out;
}
template std::vector<std::array<double, 2>> parse_points<2>(const Json&, const std::string&);
template std::vector<std::array<double, 3>> parse_points<3>(const Json&, const std::string&);

RayIn parse_ray(const Json& ray, const std::string& what) {
  only_keys(ray, {"o", "d"}, what);
  RayIn r{parse_vec<3>(ray["o"], what + ".o"), parse_vec<3>(ray["d"], what + ".d")};
  if (r.d[0] == 0 && r.d[1] == 0 && r.d[2] == 0) throw InputError(what + ".d: the direction is zero");
  return r;
}

bool operator==(const HitOutput& x, const HitOutput& y) {
  if (x.hit != y.hit) return false;
  if (!x.hit) return true;
  if (x.prim != y.prim) return false;
  if (!x.exact || !y.exact) return true;
  return x.exact->t == y.exact->t && x.exact->b == y.exact->b;
}

HitOutput make_exact_hit(bool hit, std::int32_t prim, const Rational& t, const std::array<Rational, 3>& b) {
  HitOutput o;
  o.hit = hit;
  auto e = std::make_shared<oracle::RayResult>();
  e->hit = hit;
  if (hit) {
    o.prim = prim, o.t = t.get_d(), o.b = {b[0].get_d(), b[1].get_d(), b[2].get_d()};
    e->t = t, e->b = b;
  }
  o.exact = std::move(e);
  return o;
}

Json hit_json(const HitOutput& o) {
  Json j{{"hit", o.hit}};
  if (o.hit) {
    auto num = [&](double d, const Rational* q) { return q ? Json(q->get_str()) : Json(d); };
    const oracle::RayResult* e = o.exact.get();
    j["t"] = num(o.t, e ? &e->t : nullptr);
    j["prim"] = o.prim;
    j["b"] = Json::array();
    for (int i = 0; i < 3; ++i) j["b"].push_back(num(o.b[i], e ? &e->b[i] : nullptr));
  }
  j["nodes_visited"] = o.nodes_visited;
  j["prim_tests"] = o.prim_tests;
  return j;
}

HitOutput closest_hit_oracle(const Mesh& m, const RayIn& r) {
  std::vector<oracle::Triangle3> tris;
  tris.reserve(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) tris.push_back(m.triangle<Rational>(i));
  const oracle::ClosestHit h = oracle::closest_hit(vec_from<Rational, 3>(r.o), vec_from<Rational, 3>(r.d), tris);
  return make_exact_hit(h.hit, h.prim, h.r.t, h.r.b);
}

double hit_error(const HitOutput& got, const HitOutput& exact) {
  if (!got.hit || !exact.hit || !exact.exact) return 0;
  const Rational& te = exact.exact->t;
  const Rational diff = abs(Rational((got.exact ? got.exact->t : num::to_rational(got.t)) - te));
  if (sgn(diff) == 0) return 0;
  return std::ldexp(diff.get_d(), got.bits - 1 - std::ilogb(te.get_d()));
}

bool operator==(const TreeOutput& x, const TreeOutput& y) {
  if (x.nodes.size() != y.nodes.size()) return false;
  for (std::size_t i = 0; i < x.nodes.size(); ++i) {
    const TreeNode &a = x.nodes[i], &b = y.nodes[i];
    if (a.parent != b.parent || a.children != b.children || a.prims != b.prims || a.axis != b.axis) return false;
  }
  if (!x.exact_lo.empty() && !y.exact_lo.empty()) return x.exact_lo == y.exact_lo && x.exact_hi == y.exact_hi;
  return true;
}

Rational TreeOutput::lo_at(std::size_t i, int k) const {
  const std::size_t at = i * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k);
  return exact_lo.empty() ? num::to_rational(lo[at]) : exact_lo[at];
}
Rational TreeOutput::hi_at(std::size_t i, int k) const {
  const std::size_t at = i * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k);
  return exact_hi.empty() ? num::to_rational(hi[at]) : exact_hi[at];
}

std::int32_t add_node(TreeOutput& t, std::int32_t parent) {
  const auto id = static_cast<std::int32_t>(t.nodes.size());
  t.nodes.emplace_back();
  t.nodes.back().parent = parent;
  if (parent >= 0) t.nodes[static_cast<std::size_t>(parent)].children.push_back(id);
  const std::size_t need = t.nodes.size() * static_cast<std::size_t>(t.dim);
  t.lo.resize(need), t.hi.resize(need);
  if (!t.exact_lo.empty()) t.exact_lo.resize(need), t.exact_hi.resize(need);
  return id;
}

Json tree_json(const TreeOutput& t) {
  Json nodes = Json::array();
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const TreeNode& n = t.nodes[i];
    Json lo = Json::array(), hi = Json::array();
    for (int k = 0; k < t.dim; ++k) {
      if (t.exact_lo.empty()) {
        const std::size_t at = i * static_cast<std::size_t>(t.dim) + static_cast<std::size_t>(k);
        lo.push_back(t.lo[at]), hi.push_back(t.hi[at]);
      } else {
        lo.push_back(t.lo_at(i, k).get_str()), hi.push_back(t.hi_at(i, k).get_str());
      }
    }
    Json node{{"parent", n.parent}, {"lo", lo}, {"hi", hi}};
    if (n.children.empty()) node["prims"] = n.prims;
    else node["children"] = n.children, node["axis"] = n.axis;
    nodes.push_back(std::move(node));
  }
  return {{"nodes", t.nodes.size()}, {"leaves", t.leaves}, {"depth", t.depth}, {"sah_cost", t.sah_cost}, {"bytes", t.bytes}, {"tree", std::move(nodes)}};
}

}  // namespace sw::spatial
