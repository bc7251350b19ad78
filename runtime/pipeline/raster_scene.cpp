#include "pipeline/raster_scene.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include "spatial/bvh_build.hpp"

namespace sw::pipespec {

namespace {

using tracer::ObjectKind;
using Tri = std::array<Vec3<Rational>, 3>;

Vec3<double> unit_d(const Vec3<double>& a) { return (1.0 / std::sqrt(dot(a, a))) * a; }
pipe::Vec4<Rational> point(const Vec3<Rational>& p) { return {p.x, p.y, p.z, Rational(1)}; }
pipe::Vec4<Rational> toward(const Vec3<Rational>& d) { return {d.x, d.y, d.z, Rational(0)}; }

// The tracer's camera as its double arithmetic has it (camera_ray_at, trace_scene), every value
// then taken exactly: the frame, the view plane's distance and the window on it.
pipe::RasterCamera<Rational> tracer_camera(const tracer::Camera& c, std::int64_t width, std::int64_t height) {
  if (c.projection != ray::Projection::perspective)
    throw InputError("scene.camera.projection: a rasterizer projects through a plane: perspective only, got " +
                     std::string(c.projection == ray::Projection::fisheye ? "fisheye" : "cylindrical"));
  const Vec3<double> eye{c.eye.d[0], c.eye.d[1], c.eye.d[2]}, vpn{c.vpn.d[0], c.vpn.d[1], c.vpn.d[2]}, vup{c.vup.d[0], c.vup.d[1], c.vup.d[2]};
  const Vec3<double> n = unit_d(vpn), u = unit_d(cross(vup, n)), v = cross(n, u);
  std::array<double, 4> w;
  if (c.has_window) {
    for (std::size_t k = 0; k < 4; ++k) w[k] = c.window[k].d;
  } else {
    const double fov = c.fov.d * (3.14159265358979323846 / 180);
    const double hh = c.dist.d * std::tan(fov * 0.5), hw = hh * double(width) / double(height);
    w = {-hw, hw, -hh, hh};
  }
  auto q = [](double x) { return num::to_rational(x); };
  auto q3 = [&](const Vec3<double>& x) { return Vec3<Rational>{q(x.x), q(x.y), q(x.z)}; };
  return {q3(eye), q3(u), q3(v), q3(n), q(c.dist.d), {q(w[0]), q(w[1]), q(w[2]), q(w[3])}, Rational(0), width, height, false, Rational(0)};
}

// The sphere's triangles by the documented rule: vertex (i, k) at polar angle pi i/S and azimuth
// pi k/S about +z (sphere-uv's pole), at the double nearest c + r (sin cos, sin sin, cos); the
// caps are fans of S 2 triangles about the poles, the bands quads cut along (i, k)-(i+1, k+1).
std::vector<Tri> sphere_triangles(const Vec3<Rational>& c, const Rational& r, int S) {
  const Vec3<double> cd = to_double3(c);
  const double rd = r.get_d();
  auto vertex = [&](int i, int k) {
    const double th = std::numbers::pi * i / S, ph = std::numbers::pi * k / S;
    const Vec3<double> p = i == 0 ? Vec3<double>{cd.x, cd.y, cd.z + rd}
                           : i == S ? Vec3<double>{cd.x, cd.y, cd.z - rd}
                                    : Vec3<double>{cd.x + rd * std::sin(th) * std::cos(ph), cd.y + rd * std::sin(th) * std::sin(ph), cd.z + rd * std::cos(th)};
    return Vec3<Rational>{num::to_rational(p.x), num::to_rational(p.y), num::to_rational(p.z)};
  };
  std::vector<Tri> out;
  auto push = [&](Tri t) {  // counter-clockwise seen from outside
    const Vec3<Rational> mid = Vec3<Rational>(t[0] + t[1]) + Vec3<Rational>(t[2] - Vec3<Rational>(Rational(3) * c));
    if (dot(cross(Vec3<Rational>(t[1] - t[0]), Vec3<Rational>(t[2] - t[0])), mid) < 0) std::swap(t[1], t[2]);
    out.push_back(t);
  };
  for (int i = 0; i < S; ++i)
    for (int k = 0; k < 2 * S; ++k) {
      const int k1 = (k + 1) % (2 * S);
      if (i > 0) push({vertex(i, k), vertex(i + 1, k1), vertex(i, k1)});
      if (i + 1 < S) push({vertex(i, k), vertex(i + 1, k), vertex(i + 1, k1)});
    }
  return out;
}

// The box's twelve triangles, two per face, counter-clockwise seen from outside; a flat box's
// faces of no area are left out.
std::vector<Tri> box_triangles(const Vec3<Rational>& lo, const Vec3<Rational>& hi) {
  std::vector<Tri> out;
  for (int k = 0; k < 3; ++k)
    for (int side = 0; side < 2; ++side) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      std::array<Vec3<Rational>, 4> q;
      for (int m = 0; m < 4; ++m) {
        Vec3<Rational>& p = q[m];
        p[k] = side ? hi[k] : lo[k];
        p[a] = (m == 1 || m == 2) ? hi[a] : lo[a];
        p[b] = (m >= 2) ? hi[b] : lo[b];
      }
      // (a, b) turns counter-clockwise about +k: the +k face keeps the order, the -k face reverses it.
      if (!side) std::swap(q[1], q[3]);
      for (const Tri& t : {Tri{q[0], q[1], q[2]}, Tri{q[0], q[2], q[3]}})
        if (!(cross(Vec3<Rational>(t[1] - t[0]), Vec3<Rational>(t[2] - t[0])) == Vec3<Rational>{})) out.push_back(t);
    }
  return out;
}

// Exact boxes for a BVH topology built in double, bottom up: a leaf bounds its triangles, an inner
// node its two children (children follow their parent in the node array).
std::vector<spatial::Box<Rational, 3>> exact_boxes(const spatial::Bvh<double>& top, const std::vector<Tri>& tris) {
  std::vector<spatial::Box<Rational, 3>> box(top.nodes.size());
  for (std::size_t k = top.nodes.size(); k-- > 0;) {
    const spatial::BvhNode<double>& n = top.nodes[k];
    if (n.left >= 0) {
      box[k] = box[static_cast<std::size_t>(n.left)];
      box[k].grow(box[static_cast<std::size_t>(n.right)]);
      continue;
    }
    box[k] = spatial::triangle_bounds(tris[static_cast<std::size_t>(top.order[n.first])]);
    for (std::int32_t i = n.first + 1; i < n.first + n.count; ++i) box[k].grow(spatial::triangle_bounds(tris[static_cast<std::size_t>(top.order[i])]));
  }
  return box;
}
template <class Num> spatial::Bvh<Num> bvh_of(const spatial::Bvh<double>& top, const std::vector<spatial::Box<Rational, 3>>& box) {
  spatial::Bvh<Num> out;
  out.order = top.order, out.leaves = top.leaves, out.depth = top.depth;
  for (std::size_t k = 0; k < top.nodes.size(); ++k) {
    const spatial::BvhNode<double>& n = top.nodes[k];
    spatial::BvhNode<Num> m;
    m.box = {to_num<Num>(box[k].lo), to_num<Num>(box[k].hi)};
    m.parent = n.parent, m.left = n.left, m.right = n.right, m.first = n.first, m.count = n.count, m.depth = n.depth, m.axis = n.axis;
    out.nodes.push_back(m);
  }
  return out;
}

// The eye depths of the corners of one triangle's part inside the view pyramid (the four sides'
// clip, before the near plane), in Num; none for a part that reaches the eye. With the sides'
// planes, clip z = w - 2 n w_world for any n > 0 (here n = 1/2), so a corner's world w is w - z and
// its eye depth w / (w - z); a corner at infinity (w = z) has none.
template <class Num> std::vector<Num> pyramid_depths(const pipe::Mat4<Num>& M, const pipe::RasterTriangle<Rational>& t) {
  std::array<pipe::Vec4<Num>, 3> c;
  for (int k = 0; k < 3; ++k) {
    const pipe::Vec4<Rational>& x = t.x[k];
    c[k] = pipe::apply(M, pipe::Vec4<Num>{num::from_rational<Num>(x.x), num::from_rational<Num>(x.y), num::from_rational<Num>(x.z), num::from_rational<Num>(x.w)});
  }
  NoProbe none;
  const pipe::ClippedPolygon<Num> K = pipe::clip_volume<Num>(c, none, 1);
  std::vector<Num> out;
  for (int k = 0; k < K.k; ++k) {
    const pipe::Vec4<Num>& v = K.v[k].c;
    if (v.w == Num(0)) return {};  // the eye itself: the polygon holds it, and is seen edge-on
    if (Num(0) < v.w - v.z) out.push_back(Num(v.w / (v.w - v.z)));
  }
  return out;
}

// Intervals bound every triangle's depths; the triangles that may hold the least are redone exactly.
}  // namespace

Rational near_plane(pipe::RasterCamera<Rational> cam, const std::vector<pipe::RasterTriangle<Rational>>& tris) {
  cam.near = Rational(1, 2);
  const pipe::Mat4<Rational> M = pipe::raster_matrix(cam);
  pipe::Mat4<Interval> Mi;
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) Mi[r][k] = num::from_rational<Interval>(M[r][k]);
  double upper = INFINITY;
  std::vector<std::pair<double, std::size_t>> lower;  // per triangle in view: its least depth's lower bound
  std::vector<std::size_t> exact;                     // triangles the intervals could not clip
  for (std::size_t i = 0; i < tris.size(); ++i) {
    try {
      const std::vector<Interval> d = pyramid_depths(Mi, tris[i]);
      if (d.empty()) continue;
      double lo = INFINITY;
      for (const Interval& x : d) lo = std::min(lo, x.lo()), upper = std::min(upper, x.hi());
      lower.push_back({lo, i});
    } catch (const Uncertain&) {
      exact.push_back(i);
    }
  }
  for (const auto& [lo, i] : lower)
    if (lo <= upper) exact.push_back(i);
  std::optional<Rational> least;
  for (std::size_t i : exact)
    for (const Rational& d : pyramid_depths(M, tris[i]))
      if (!least || d < *least) least = d;
  return least ? Rational(*least / 2) : cam.dist;
}

ray::Ray3<Rational> pixel_ray(const pipe::RasterCamera<Rational>& c, std::int64_t i, std::int64_t j) {
  const Rational half(1, 2);
  const Rational wu = c.window[0] + (Rational(i) + half) * (c.window[1] - c.window[0]) / Rational(c.width);
  const Rational wv = c.window[3] - (Rational(j) + half) * (c.window[3] - c.window[2]) / Rational(c.height);
  const Vec3<Rational> across = Vec3<Rational>(wu * c.u) + Vec3<Rational>(wv * c.v);
  // Orthographic: parallel rays down -n from the near plane, one unit of eye depth a unit of t
  // (the frame's inverse turns n into eye space's z, so that direction is B (0, 0, -1)).
  if (c.orthographic) return {c.eye + across + Vec3<Rational>(Rational(-c.near) * c.n), Vec3<Rational>(Rational(-1) * c.n)};
  const Vec3<Rational> d = Vec3<Rational>(Rational(-c.dist) * c.n) + across;
  return {c.eye + Vec3<Rational>(Rational(c.near / c.dist) * d), d};
}

std::shared_ptr<const RasterScene> raster_scene(std::shared_ptr<const tracer::Scene> scene, const RasterOptions& o) {
  if (o.stacks < kMinStacks || o.stacks > kMaxStacks)
    throw InputError("stacks: a sphere's bands of latitude, in [" + std::to_string(kMinStacks) + ", " + std::to_string(kMaxStacks) + "], got " + std::to_string(o.stacks));
  auto out = std::make_shared<RasterScene>();
  RasterScene& s = *out;
  const tracer::Scene& sc = *scene;
  s.scene = std::move(scene);
  s.width = o.width > 0 ? o.width : sc.camera.width;
  s.height = o.height > 0 ? o.height : sc.camera.height;
  s.stacks = o.stacks;
  s.camera = tracer_camera(sc.camera, s.width, s.height);
  for (std::size_t k = 0; k < sc.objects.size(); ++k) {
    const tracer::Object& ob = sc.objects[k];
    RasterObject ro{ob.kind, std::int32_t(s.tris.size()), 0};
    tracer::Prim<Rational> prim;
    prim.shape = ob.kind == ObjectKind::plane || ob.kind == ObjectKind::triangle ? ob.kind : ObjectKind::mesh;
    prim.material = ob.material;
    auto add = [&](const std::array<pipe::Vec4<Rational>, 3>& x, const std::array<Vec3<double>, 3>& n) {
      s.tris.push_back({x, std::int32_t(k), ro.count++});
      s.normals.push_back(n);
    };
    auto add_mesh = [&](const std::vector<Tri>& tris, auto&& corner_normal) {
      for (std::size_t i = 0; i < tris.size(); ++i)
        add({point(tris[i][0]), point(tris[i][1]), point(tris[i][2])}, {corner_normal(i, 0), corner_normal(i, 1), corner_normal(i, 2)});
      std::vector<std::array<Vec3<double>, 3>> d(tris.size());
      for (std::size_t i = 0; i < tris.size(); ++i) d[i] = {to_double3(tris[i][0]), to_double3(tris[i][1]), to_double3(tris[i][2])};
      NoProbe none;
      const spatial::Bvh<double> topology = spatial::bvh_build<double>(d, none);
      const std::vector<spatial::Box<Rational, 3>> boxes = exact_boxes(topology, tris);
      tracer::MeshData<Rational> m{tris, bvh_of<Rational>(topology, boxes)};
      tracer::MeshData<Interval> mi;
      for (const Tri& t : tris) mi.tris.push_back({to_num<Interval>(t[0]), to_num<Interval>(t[1]), to_num<Interval>(t[2])});
      mi.bvh = bvh_of<Interval>(topology, boxes);
      prim.mesh = std::int32_t(s.traced.meshes.size());
      s.traced.meshes.push_back(std::move(m));
      s.traced_iv.meshes.push_back(std::move(mi));
    };
    auto face_normal = [](const Tri& t) {
      const Vec3<double> a = to_double3(t[0]), b = to_double3(t[1]), c = to_double3(t[2]);
      return unit_d(cross(Vec3<double>(b - a), Vec3<double>(c - a)));
    };
    switch (ob.kind) {
      case ObjectKind::sphere: {
        const std::vector<Tri> tris = sphere_triangles(ob.a.q, ob.radius.q, s.stacks);
        const Vec3<double> c = to_double3(ob.a.q);
        add_mesh(tris, [&](std::size_t i, int v) { return unit_d(to_double3(tris[i][v]) - c); });
        break;
      }
      case ObjectKind::box: {
        const std::vector<Tri> tris = box_triangles(ob.a.q, ob.b.q);
        add_mesh(tris, [&](std::size_t i, int) { return face_normal(tris[i]); });
        break;
      }
      case ObjectKind::mesh: {
        const spatial::Mesh& file = *sc.meshes[static_cast<std::size_t>(ob.mesh)].mesh;
        std::vector<Vec3<Rational>> placed(file.v.size());
        for (std::size_t v = 0; v < file.v.size(); ++v) {
          const auto& x = file.v[v];
          placed[v] = Vec3<Rational>(ob.scale.q * Vec3<Rational>{num::to_rational(x[0]), num::to_rational(x[1]), num::to_rational(x[2])}) + ob.translate.q;
        }
        std::vector<Tri> tris(file.size());
        std::vector<Vec3<double>> smooth(file.v.size()), face(file.size());
        for (std::size_t i = 0; i < file.size(); ++i) {
          std::array<Vec3<double>, 3> d;
          for (int v = 0; v < 3; ++v) tris[i][v] = placed[static_cast<std::size_t>(file.f[i][v])], d[v] = to_double3(tris[i][v]);
          face[i] = cross(Vec3<double>(d[1] - d[0]), Vec3<double>(d[2] - d[0]));  // its length: twice the area, the average's weight
          for (int v = 0; v < 3; ++v) smooth[static_cast<std::size_t>(file.f[i][v])] = smooth[static_cast<std::size_t>(file.f[i][v])] + face[i];
        }
        add_mesh(tris, [&](std::size_t i, int v) {
          const Vec3<double>& a = smooth[static_cast<std::size_t>(file.f[i][v])];
          return dot(a, a) > 0 ? unit_d(a) : dot(face[i], face[i]) > 0 ? unit_d(face[i]) : Vec3<double>{0, 0, 1};
        });
        break;
      }
      case ObjectKind::triangle: {
        const Tri t{ob.v[0].q, ob.v[1].q, ob.v[2].q};
        const Vec3<double> n = face_normal(t);
        add({point(t[0]), point(t[1]), point(t[2])}, {n, n, n});
        prim.v = t;
        break;
      }
      case ObjectKind::plane: {
        // Four wedges from the point to infinity along +-A and +-B, A x B along the normal.
        const Vec3<Rational>& p = ob.a.q;
        const Vec3<Rational>& nv = ob.b.q;
        const Rational ax = num::abs(nv.x), ay = num::abs(nv.y), az = num::abs(nv.z);
        const int m = ax <= ay && ax <= az ? 0 : ay <= az ? 1 : 2;
        Vec3<Rational> e{};
        e[m] = 1;
        // Scaled by a power of two to the size of the point and the eye: the same wedges exactly,
        // but a rounded cut between p and a point at infinity then blends numbers of one size.
        const double size = std::max({1.0, std::abs(to_double3(p).x), std::abs(to_double3(p).y), std::abs(to_double3(p).z),
                                      std::abs(s.camera.eye.x.get_d()), std::abs(s.camera.eye.y.get_d()), std::abs(s.camera.eye.z.get_d())});
        const Vec3<Rational> A0 = cross(nv, e), B0 = cross(nv, A0);
        const auto scaled = [&](const Vec3<Rational>& d) {
          const Vec3<double> x = to_double3(d);
          const double m = std::max({std::abs(x.x), std::abs(x.y), std::abs(x.z)});
          return Vec3<Rational>(num::to_rational(std::exp2(std::round(std::log2(size / m)))) * d);
        };
        const Vec3<Rational> A = scaled(A0), B = scaled(B0);
        const Vec3<Rational> mA = Rational(-1) * A, mB = Rational(-1) * B;
        const Vec3<double> n = unit_d(to_double3(nv));
        for (const auto& [a, b] : {std::pair{A, B}, std::pair{B, mA}, std::pair{mA, mB}, std::pair{mB, A}}) add({point(p), toward(a), toward(b)}, {n, n, n});
        prim.a = p, prim.b = nv;
        break;
      }
    }
    s.objects.push_back(ro);
    s.traced.objects.push_back(prim);
    tracer::Prim<Interval> pi;
    pi.shape = prim.shape, pi.material = prim.material, pi.mesh = prim.mesh;
    pi.a = to_num<Interval>(prim.a), pi.b = to_num<Interval>(prim.b);
    for (int v = 0; v < 3; ++v) pi.v[v] = to_num<Interval>(prim.v[v]);
    s.traced_iv.objects.push_back(pi);
  }
  s.camera.near = near_plane(s.camera, s.tris);
  return out;
}

RasterPixels draw(const RasterScene& s, Numeric n, bool* fell_back) {
  return in_mode(n, "scene-raster", fell_back, [&]<class Num>(std::type_identity<Num>) {
    NoProbe none;
    return raster_pixels(s, pipe::scene_raster<Num>(camera_in<Num>(s.camera), triangles_in<Num>(s.tris), none));
  });
}

}  // namespace sw::pipespec
