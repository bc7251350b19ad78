// The spatial family's shared inputs: coordinates (doubles, -0 kept), inline triangles, and the
// OFF and OBJ readers — checked against tinyobjloader on the same OBJ text, and on bad files,
// which must fail with one line naming the file and line.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <random>
#include "cli_harness.hpp"
#include "spatial/spatial_common.hpp"

using namespace sw;
using sw::testing::scratch;

namespace {

std::string write(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const auto p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string error_of(const std::string& path) {
  try {
    (void)spatial::read_mesh_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("spatial coordinates are doubles, -0 is kept, other rationals are refused", "[spatial][spatial-input]") {
  CHECK(spatial::parse_coord(Json(0.5), "x") == 0.5);
  CHECK(spatial::parse_coord(Json("1/4"), "x") == 0.25);
  CHECK(std::signbit(spatial::parse_coord(Json::parse("-0.0"), "x")));
  CHECK_THROWS_WITH(spatial::parse_coord(Json("1/3"), "x"), Catch::Contains("not a double"));
  CHECK_THROWS_WITH(spatial::parse_coord(Json(2e15), "x"), Catch::Contains("x"));
  CHECK_THROWS_AS(spatial::parse_coord(Json("nan"), "x"), InputError);
  CHECK_THROWS_WITH(spatial::parse_ray(Json::parse(R"({"o":[0,0,0],"d":[0,-0.0,0]})"), "ray"), Catch::Contains("direction is zero"));
}

TEST_CASE("inline triangles and their errors", "[spatial][spatial-input]") {
  const spatial::Mesh m = spatial::parse_mesh(Json::parse(R"({"triangles":[[[0,0,0],[1,0,0],[0,1,0]],[[0,0,1],[1,0,1],[0,1,1]]]})"), "input");
  REQUIRE(m.size() == 2);
  CHECK(m.triangle<double>(1)[2].y == 1);
  CHECK(m.triangle<Rational>(1)[0].z == 1);
  CHECK_THROWS_WITH(spatial::parse_mesh(Json::parse(R"({})"), "input"), Catch::Contains("exactly one of"));
  CHECK_THROWS_WITH(spatial::parse_mesh(Json::parse(R"({"triangles":[[[0,0,0],[1,0,0]]]})"), "input"), Catch::Contains("input.triangles[0]"));
  CHECK_THROWS_WITH(spatial::parse_mesh(Json::parse(R"({"triangles":[]})"), "input"), Catch::Contains("non-empty"));
}

TEST_CASE("OFF: counts on the header line or their own, comments, polygons as fans", "[spatial][spatial-input]") {
  const auto dir = scratch("spatial-off");
  const spatial::Mesh a = spatial::read_mesh_file(write(dir, "a.off", "OFF 4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"));
  const spatial::Mesh b = spatial::read_mesh_file(write(dir, "b.off", "OFF\n# a square\n4 1 0\n\n0 0 0\n1 0 0 # x\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
  REQUIRE(a.size() == 2);
  REQUIRE(b.size() == 2);
  CHECK(a.f == b.f);
  CHECK(a.v == b.v);
}

TEST_CASE("OBJ: our reader gives tinyobjloader's triangles on the same text", "[spatial][spatial-input]") {
  const auto dir = scratch("spatial-obj");
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> u(-10, 10);
  std::string text = "# generated\no thing\n";
  const int nv = 60;
  for (int i = 0; i < nv; ++i) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", u(rng), u(rng), u(rng));
    text += buf;
  }
  text += "vt 0 0\nvn 0 0 1\n";
  // Triangles only: tinyobjloader splits a quad along its shorter diagonal, we fan it (checked below).
  for (int f = 0; f < 80; ++f) {  // the index forms "i", "i/t", "i//n", "i/t/n" and negatives
    const int n = 3;
    text += "f";
    for (int k = 0; k < n; ++k) {
      const int i = 1 + int(rng() % nv);
      const int form = int(rng() % 5);
      const std::string idx = form == 4 ? std::to_string(i - nv - 1) : std::to_string(i);  // -1 is the last vertex
      text += " " + idx + (form == 1 ? "/1" : form == 2 ? "//1" : form == 3 ? "/1/1" : "");
    }
    text += "\n";
  }
  const std::string path = write(dir, "m.obj", text);
  const spatial::Mesh ours = spatial::read_mesh_file(path);

  tinyobj::ObjReader reader;
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.triangulation_method = "simple";  // fans, as ours
  REQUIRE(reader.ParseFromFile(path, config));
  const auto& attrib = reader.GetAttrib();
  std::vector<std::array<double, 9>> theirs;
  for (const auto& shape : reader.GetShapes())
    for (std::size_t f = 0; f * 3 < shape.mesh.indices.size(); ++f) {
      std::array<double, 9> t{};
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) t[3 * c + k] = attrib.vertices[3 * std::size_t(shape.mesh.indices[3 * f + c].vertex_index) + k];
      theirs.push_back(t);
    }
  REQUIRE(ours.size() == theirs.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    const auto t = ours.triangle<double>(i);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) differ += float(t[c][k]) != float(theirs[i][3 * c + k]);  // tinyobjloader reads floats
  }
  CHECK(differ == 0);

  // A polygon is a fan from its first corner: f a b c d e gives (a,b,c), (a,c,d), (a,d,e).
  const std::string poly = write(dir, "p.obj", "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 -1\n");
  const spatial::Mesh fan = spatial::read_mesh_file(poly);
  REQUIRE(fan.size() == 3);
  const double xs[5] = {0, 1, 2, 1, 0}, ys[5] = {0, 0, 1, 2, 1};
  for (int t = 0; t < 3; ++t) {
    const auto tri = fan.triangle<double>(std::size_t(t));
    const int corner[3] = {0, t + 1, t + 2};
    for (int c = 0; c < 3; ++c) {
      CHECK(tri[c][0] == xs[corner[c]]);
      CHECK(tri[c][1] == ys[corner[c]]);
    }
  }
}

TEST_CASE("bad mesh files fail with one line naming the file and the line", "[spatial][spatial-input]") {
  const auto dir = scratch("spatial-bad-mesh");
  struct Case {
    const char* name;
    const char* text;
    const char* says;
  };
  const Case cases[] = {
      {"a.off", "OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n", "a.off:4: coordinate nan"},
      {"b.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "b.off:6: vertex index 7 out of range"},
      {"c.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "c.off:6: the file ends after 1 of 2 faces"},
      {"d.off", "PLY\n", "d.off:1: expected the OFF header"},
      {"e.off", "OFF\n3 1 0\n0 0 0\n1 0 1e400\n0 1 0\n3 0 1 2\n", "e.off:4:"},
      {"f.off", "OFF\n3 1 0\n0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n", "f.off:4: 'x' is not a number"},
      {"g.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "g.off:6: a face of 2 vertices"},
      {"h.off", "", "h.off: empty file"},
      {"i.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n", "i.obj:3: vertex index 2 out of range"},
      {"j.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "j.obj:4: 'x' is not a vertex index"},
      {"k.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "k.obj: no faces"},
      {"l.obj", "v 0 0\nf 1 1 1\n", "l.obj:1: expected a coordinate"},
      {"m.stl", "solid\n", "m.stl: expected a .off or .obj mesh file"},
  };
  for (const Case& c : cases) {
    const std::string err = error_of(write(dir, c.name, c.text));
    INFO(c.name << ": " << err);
    CHECK(err.find(c.says) != std::string::npos);
    CHECK(err.find('\n') == std::string::npos);
  }
  CHECK_THAT(error_of((dir / "missing.off").string()), Catch::Contains("cannot read the mesh file"));
  std::string long_line = "OFF\n3 1 0\n0 0 " + std::string(5000, '1') + "\n";
  CHECK_THAT(error_of(write(dir, "long.off", long_line)), Catch::Contains("long.off:3: a line longer than 4096"));
}
