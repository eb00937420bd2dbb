#include <rast/properties.h>
#include <rast/property_generators.h>

#include <string_view>
#include <utility>

namespace rast::gen {

rc::Gen<Scene> scenes_for(std::string_view property) {
    if (property == "watertight" || property == "area_tiling")
        return rc::gen::oneOf(triangulated_region(),
                              rc::gen::exec([] { return *triangulated_region_on_grid(*rc::gen::element(4, 8, 16)); }));
    if (property == "order_independence")
        return rc::gen::weightedOneOf<Scene>({{3, overlapping_triangles()}, {1, stamped_runs()}, {1, any_scene()}});
    if (property == "fixed_matches_reference")
        return rc::gen::weightedOneOf<Scene>({{3, any_scene()}, {1, stamped_runs()}});
    if (property == "conforms")
        return rc::gen::oneOf(any_scene(), overlapping_triangles(), triangulated_region());
    if (property == "float_within_bound") return rc::gen::oneOf(any_scene(), long_rows());
    if (property == "msaa_counts")
        return rc::gen::map(rc::gen::pair(any_scene(), rc::gen::element(4, 8, 16)), [](std::pair<Scene, int> p) {
            p.first.samples = p.second;
            return p.first;
        });
    if (property == "visible_area" || property == "msaa_visible_bound")
        return small_window(rc::gen::weightedOneOf<Scene>(
            {{2, layered_triangles()}, {2, overlapping_triangles()}, {1, triangulated_region()}, {1, loose_triangles()}}));
    if (property == "lines_zbuffer") return lines_among_triangles();
    properties::property(property);  // throws for a name that is not a property
    return any_scene();
}

}  // namespace rast::gen
