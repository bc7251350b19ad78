// shadow-volume step by step in exact mode: the eye's pass against a standalone scene-raster (its
// nested steps value for value), each face's clip against a standalone clip-volume, and the rest
// against closed forms written here: a caster's side of the light from its normal, the silhouette
// by a brute-force edge count, every face corner the eye's matrix applied to a mesh corner or its
// extrusion, every fragment's depth from the window plane of its triangle and the stored depth,
// both counts kept here, and each pixel's count equal to the oracle's (no rasterization).
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include "corpus.hpp"
#include "shadows/shadow_volume_input.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::shadowspec;

namespace {

using V3 = Vec3<Rational>;
using V4 = pipe::Vec4<Rational>;

// The light's side of a triangle: its normal from the first corner (a corner at infinity is a
// direction) dotted with the way to the light.
Rational side_of(const std::array<V4, 3>& x, const V4& L) {
  auto dir = [&](int k) {
    const V4& b = x[std::size_t(k)];
    return b.w == 0 ? V3{b.x, b.y, b.z} : V3{b.x - x[0].x, b.y - x[0].y, b.z - x[0].z};
  };
  const V3 n = cross(dir(1), dir(2));
  return dot(n, L.w == 0 ? V3{L.x, L.y, L.z} : V3{L.x - x[0].x, L.y - x[0].y, L.z - x[0].z});
}

// The 3D view's items: a triangle at three points, kept, with its label.
void check_shown(StepGeometry& g, const char* label, const std::array<V3, 3>& p) {
  GeoItem& item = g.take(GeoKind::triangle3);
  CHECK(item.values == std::vector<Rational>{p[0].x, p[0].y, p[0].z, p[1].x, p[1].y, p[1].z, p[2].x, p[2].y, p[2].z});
  CHECK(item.label == label);
  CHECK(item.life == "keep");
}

}  // namespace

TEST_CASE("shadow-volume: every exact step against standalone passes and closed forms", "[shadows][volume][steps]") {
  std::vector<Json> inputs{Json::parse(R"({"scene":"scenes/eye-in-shadow.json","size":[20,15],"stacks":3,"method":"zpass"})"),
                           Json::parse(R"({"scene":"scenes/glass-spheres.json","size":[12,9],"stacks":3,"light":1})"),
                           // A light under the floor: the floor's wedges face away and are turned.
                           Json::parse(R"({"scene":{"camera":{"eye":[0,3,6],"vpn":[0,0.5,1],"vup":[0,1,0],"d":1,"fov":50,"resolution":[12,9]},
                              "materials":{"m":{"diffuse":[0.8,0.8,0.8]}},"lights":[{"type":"point","position":[1,-2,0]}],
                              "objects":[{"type":"plane","point":[0,0,0],"normal":[0,1,0],"material":"m"},
                                         {"type":"triangle","vertices":[[-1,1,0],[1,1,0],[0,2,1]],"material":"m"}]},"size":[12,9]})")};
  for (const Json& j : corpus("shadows", "shadow-volume")) inputs.push_back(j);
  std::size_t fragments = 0, flipped = 0, pixels = 0;
  for (const Json& j : inputs) {
    INFO(j.dump().substr(0, 240));
    const auto in = parse_volume_input(j).p;
    const RasterScene& sc = *in->seen->scene;
    const auto tris = pipespec::triangles_in<Rational>(sc.tris);
    const V4& L = in->light;
    Recorder<Rational> t;
    (void)shadow::shadow_volume<Rational>(sc.camera, tris, in->mesh, L, in->zfail, t);
    Recorder<Rational> eye_steps;
    const pipe::DepthBuffer<Rational> eye = pipe::scene_raster<Rational>(sc.camera, tris, eye_steps).buffer;
    const pipe::Mat4<Rational> M = pipe::raster_matrix(sc.camera);
    const VolumePixels oracle = volume_oracle(*in);
    // Every corner a face may have, in clip space.
    std::set<std::array<Rational, 4>> corners;
    for (const V4& x : in->mesh.corners)
      for (const V4& y : {x, shadow::extruded(x, L)}) {
        const V4 c = pipe::apply(M, y);
        corners.insert({c.x, c.y, c.z, c.w});
      }
    // The silhouette by brute force: each caster's directed edges, less their reverses.
    std::map<std::pair<std::int32_t, std::int32_t>, std::int64_t> net;
    std::int64_t casters = 0;
    const std::int64_t w = sc.width, h = sc.height;
    std::vector<std::int64_t> pass(std::size_t(w * h), 0), fail(std::size_t(w * h), 0);
    std::size_t nested = 0, t_index = 0;
    bool after_depth = false, front = false;
    Recorder<Rational> clip_alone;
    std::size_t clip_at = 0;
    std::array<Vec3<Rational>, 3> window{};
    std::int64_t fi = 0, fj = 0;
    Rational d, D;
    std::int64_t faces_seen = 0, lit = 0;
    // The 3D view's closed forms: the finite corners' widest extent (at least 1); a point at
    // infinity drawn that far beyond a finite point along its L-infinity unit direction; a corner
    // extruded from the light.
    Rational reach = 1;
    for (int a = 0; a < 3; ++a) {
      std::optional<Rational> lo, hi;
      for (const V4& x : in->mesh.corners)
        if (x.w != 0) {
          const Rational v = (a == 0 ? x.x : a == 1 ? x.y : x.z) / x.w;
          lo = lo ? std::min(*lo, v) : v, hi = hi ? std::max(*hi, v) : v;
        }
      if (lo) reach = std::max(reach, Rational(*hi - *lo));
    }
    auto beyond = [&](const V3& from, const V3& dir) {
      const Rational n = std::max({abs(dir.x), abs(dir.y), abs(dir.z)});
      return V3{from.x + reach / n * dir.x, from.y + reach / n * dir.y, from.z + reach / n * dir.z};
    };
    auto point_of = [](const V4& x) { return V3{x.x / x.w, x.y / x.w, x.z / x.w}; };
    auto far_of = [&](std::int32_t i) {
      const V3 x = point_of(in->mesh.corners[std::size_t(i)]);
      return beyond(x, L.w == 0 ? V3{-L.x, -L.y, -L.z} : V3{x.x - L.x / L.w, x.y - L.y / L.w, x.z - L.z / L.w});
    };
    auto finite_corners = [&](std::initializer_list<std::int32_t> ks) {
      return std::all_of(ks.begin(), ks.end(), [&](std::int32_t i) { return in->mesh.corners[std::size_t(i)].w != 0; });
    };
    std::vector<std::array<std::int32_t, 3>> caster_corners;  // in order, turned to face the light
    for_each_step<shadow::ShadowVolume>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "depth") {
        after_depth = true;
        CHECK(sv["passed"] == eye.passed);
        CHECK(nested == eye_steps.size());
        GeoItem& eye_point = g.take(GeoKind::point3);
        CHECK(eye_point.values == std::vector<Rational>{sc.camera.eye.x, sc.camera.eye.y, sc.camera.eye.z});
        CHECK(eye_point.label == "eye");
        if (L.w != 0) {
          GeoItem& light = g.take(GeoKind::point3);
          CHECK(light.values == std::vector<Rational>{L.x / L.w, L.y / L.w, L.z / L.w});
          CHECK(light.label == "light");
        }
        for (const auto& tri : tris) {
          const auto first = std::find_if(tri.x.begin(), tri.x.end(), [](const V4& x) { return x.w != 0; });
          if (first == tri.x.end()) continue;
          std::array<V3, 3> p;
          for (int k = 0; k < 3; ++k) {
            const V4& x = tri.x[std::size_t(k)];
            p[std::size_t(k)] = x.w != 0 ? point_of(x) : beyond(point_of(*first), V3{x.x, x.y, x.z});
          }
          check_shown(g, "scene", p);
        }
      } else if (line == "caster") {
        t_index = std::size_t(sv["t"].get_num().get_si());
        const auto& k = in->mesh.tris[t_index];
        CHECK(sv["s"] == side_of({in->mesh.corners[std::size_t(k[0])], in->mesh.corners[std::size_t(k[1])], in->mesh.corners[std::size_t(k[2])]}, L));
      } else if (line == "turn") {
        CHECK(sv["t"] == std::int64_t(t_index));
        const auto& k = in->mesh.tris[t_index];
        const Rational s = side_of({in->mesh.corners[std::size_t(k[0])], in->mesh.corners[std::size_t(k[1])], in->mesh.corners[std::size_t(k[2])]}, L);
        if (sv.v.count("edge_on")) {
          CHECK(sv["edge_on"] == int(s == 0));
          CHECK((s == 0 || (s < 0 && in->mesh.closed[t_index])));
        } else {
          CHECK(sv["turned"] == int(s < 0));
          auto c = k;
          if (s < 0) std::swap(c[1], c[2]);
          ++casters, caster_corners.push_back(c);
          for (int e = 0; e < 3; ++e) ++net[{c[std::size_t(e)], c[std::size_t((e + 1) % 3)]}];
        }
      } else if (line == "edges") {
        std::int64_t silhouette = 0, undirected = 0;
        for (const auto& [e, n] : net) {
          const auto back = net.find({e.second, e.first});
          silhouette += n - (back == net.end() ? 0 : back->second) > 0;
          undirected += e.first < e.second || back == net.end();
        }
        CHECK(sv["casters"] == casters);
        CHECK(sv["edges"] == undirected);
        CHECK(sv["silhouette"] == silhouette);
      } else if (line == "extrude") {
        CHECK(sv["corners"] == std::int64_t(in->mesh.corners.size()));
        CHECK(sv["directional"] == int(L.w == 0));
      } else if (line == "caps") {
        CHECK(sv["caps"] == 2 * casters);
        for (const auto& k : caster_corners)
          if (finite_corners({k[0], k[1], k[2]})) {
            const auto& x = in->mesh.corners;
            check_shown(g, "near cap", {point_of(x[std::size_t(k[0])]), point_of(x[std::size_t(k[1])]), point_of(x[std::size_t(k[2])])});
            check_shown(g, "far cap", {far_of(k[0]), far_of(k[2]), far_of(k[1])});
          }
      } else if (line == "sides") {
        std::int64_t sides = 0;
        for (const auto& [e, n] : net) {
          const auto back = net.find({e.second, e.first});
          const std::int64_t m = n - (back == net.end() ? 0 : back->second);
          sides += std::max<std::int64_t>(0, m);
        }
        // The drawn sides: each silhouette edge (a, b) once, by its lower corner index first.
        std::set<std::pair<std::int32_t, std::int32_t>> undirected;
        for (const auto& [e, n] : net) undirected.insert({std::min(e.first, e.second), std::max(e.first, e.second)});
        for (const auto& [lo, hi] : undirected) {
          const auto count = [&](std::int32_t a, std::int32_t b) { const auto it = net.find({a, b}); return it == net.end() ? 0 : it->second; };
          const std::int64_t m = count(lo, hi) - count(hi, lo);
          if (m == 0 || !finite_corners({lo, hi})) continue;
          const std::int32_t a = m > 0 ? lo : hi, b = m > 0 ? hi : lo;
          const V3 pa = point_of(in->mesh.corners[std::size_t(a)]), pb = point_of(in->mesh.corners[std::size_t(b)]);
          check_shown(g, "side quad", {pb, pa, far_of(a)});
          check_shown(g, "side quad", {pb, far_of(a), far_of(b)});
        }
        CHECK(sv["faces"] == 2 * casters + 2 * sides);
      } else if (line == "face") {
        CHECK(sv["face"] == faces_seen++);
        flipped += sv["flip"] == 1;
        std::array<pipe::Vec4<Rational>, 3> c;
        for (int k = 0; k < 3; ++k) {
          const std::string n = "c" + std::to_string(k);
          c[std::size_t(k)] = {sv[n + "[0]"], sv[n + "[1]"], sv[n + "[2]"], sv[n + "[3]"]};
          CHECK(sv[n + ".size"] == 4);
          CHECK(corners.count({c[std::size_t(k)].x, c[std::size_t(k)].y, c[std::size_t(k)].z, c[std::size_t(k)].w}));
        }
        clip_alone = Recorder<Rational>{};
        (void)pipe::clip_volume<Rational>(c, clip_alone);
        clip_at = 0;
      } else if (line == "cover") {
        const auto& poly = g.take(GeoKind::polygon).values;
        REQUIRE(poly.size() == 6);
        for (int k = 0; k < 3; ++k) window[std::size_t(k)] = {poly[std::size_t(2 * k)], poly[std::size_t(2 * k + 1)], Rational(0)};
        const Rational area2 = (window[1].x - window[0].x) * (window[2].y - window[0].y) - (window[1].y - window[0].y) * (window[2].x - window[0].x);
        CHECK(sv["area2"] == area2);
        front = sv["front"] == 1;
        CHECK(sv["samples"] == std::int64_t(pipe::covered_samples(window, w, h).size()));
      } else if (line == "fragment") {
        fi = sv["i"].get_num().get_si(), fj = sv["j"].get_num().get_si();
        CHECK(g.take(GeoKind::pixel).values == std::vector<Rational>{Rational(fi), Rational(fj)});
        d = sv["d"], D = sv["D"];
        CHECK(D == eye.depth[std::size_t(fj * w + fi)]);
        CHECK(d >= 0);
        CHECK(d <= 1);
        ++fragments;
      } else if (line == "zpass") {
        CHECK(d < D);
        pass[std::size_t(fj * w + fi)] += front ? 1 : -1;
        CHECK(sv["pass"] == pass[std::size_t(fj * w + fi)]);
      } else if (line == "zfail") {
        CHECK(!(d < D));
        fail[std::size_t(fj * w + fi)] += front ? -1 : 1;
        CHECK(sv["fail"] == fail[std::size_t(fj * w + fi)]);
      } else if (line == "lit") {
        const std::int64_t i = sv["i"].get_num().get_si(), j = sv["j"].get_num().get_si();
        auto& px = g.take(GeoKind::pixel);
        CHECK(px.values == std::vector<Rational>{Rational(i), Rational(j)});
        const std::size_t at = std::size_t(j * w + i), top = std::size_t((h - 1 - j) * w + i);
        CHECK(eye.id[at] >= 0);
        const std::int64_t count = in->zfail ? fail[at] : pass[at];
        CHECK(sv["count"] == count);
        CHECK(sv["lit"] == int(count == 0));
        CHECK(px.value == Rational(count == 0));
        CHECK(count == (in->zfail ? oracle.zfail[top] : oracle.zpass[top]));  // the closed form's count
        lit += count == 0, ++pixels;
      } else if (line == "done") {
        CHECK(sv["faces"] == faces_seen);
        CHECK(sv["fragments"] == std::int64_t(fragments));
        CHECK(sv["lit"] == lit);
      } else {
        FAIL("unexpected line " << line);
      }
    }, [&](std::size_t s) {
      if (!after_depth) {  // the eye's pass repeats the standalone scene-raster's steps
        REQUIRE(nested < eye_steps.size());
        CHECK(values_of(t, s).v == values_of(eye_steps, nested).v);
        CHECK(t.at(s).line == eye_steps.at(nested).line);
        ++nested;
        return;
      }
      REQUIRE(clip_at < clip_alone.size());  // a face's clip repeats a standalone clip-volume's
      CHECK(t.scope_id(t.at(s).scope) == pipe::ClipVolume::id);
      CHECK(values_of(t, s).v == values_of(clip_alone, clip_at).v);
      CHECK(t.at(s).line == clip_alone.at(clip_at).line);
      ++clip_at;
    });
    fragments = 0;
  }
  CHECK(pixels > 300);
  CHECK(flipped > 0);
}
