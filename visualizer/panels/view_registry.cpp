#include "panels/view_registry.hpp"
#include "panels/image_view.hpp"
#include "panels/lobe_view.hpp"
#include "panels/orbit_canvas.hpp"
#include "panels/pixel_canvas.hpp"
#include "panels/plot_view.hpp"
#include "panels/scene_view.hpp"
#include "panels/table_view.hpp"
#include "panels/tree_view.hpp"

namespace sw::vis {
namespace {

template <class C> std::unique_ptr<Canvas> make_with(TextureHost& t) {
  if constexpr (std::is_constructible_v<C, TextureHost&>) return std::make_unique<C>(t);
  else return std::make_unique<C>();
}

constexpr ViewInfo kViews[] = {
    {View::plane2d, "Plane", "The pixels and the 2D geometry of each step", make_with<PixelCanvas>},
    {View::orbit3d, "3D", "The scene under an orbit camera", make_with<OrbitCanvas>},
    {View::table, "Table", "One row per step (or per iteration), one column per recorded variable", make_with<TableCanvas>},
    {View::image, "Sweep", "The algorithm run over a grid of inputs, against exact", make_with<ImageCanvas>},
    {View::plot, "Plot", "A column of the table over its rows, against an exact run", make_with<PlotCanvas>},
    {View::tree, "Tree", "The tree's nodes: built so far, the current node, the traversal stack", make_with<TreeCanvas>},
    {View::lobe, "Lobe", "The term as a polar plot over the eye's directions in the plane of incidence, against the reference", make_with<LobeCanvas>},
    {View::scene, "Scene", "The rendered scene: click a pixel to trace its history; the planner's decisions and the ray tree", make_with<SceneCanvas>},
};
static_assert(std::size(kViews) == kViewNames.size(), "one registry entry per View");

}  // namespace

const ViewInfo& view_info(View view) { return kViews[static_cast<std::size_t>(view)]; }

std::unique_ptr<Canvas> make_canvas(View view, TextureHost& textures) { return view_info(view).make(textures); }

}  // namespace sw::vis
