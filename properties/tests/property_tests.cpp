// The properties of rast/properties.h as RapidCheck properties, each held by the reference and by the
// fast path in every precision mode it applies to. CI runs them with a fixed seed (RC_PARAMS in ctest);
// scripts/property-campaign runs them long.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rast/plugin_engine.h>

#include <cstdlib>

#include "property_harness.h"

namespace {

using rast::harness::hold;
using rast::gen::scenes_for;

// rast's own engines, and the plugin $RAST_PROPERTY_PLUGIN names when it is set: the properties its
// contract implies hold on it too (rast conform runs the same properties as a command).
const std::vector<rast::Engine>& engines() {
    static const auto all = [] {
        auto engines = rast::all_engines();
        if (const char* plugin = std::getenv("RAST_PROPERTY_PLUGIN"); plugin && *plugin)
            engines.push_back(rast::plugin_engine(plugin));
        return engines;
    }();
    return all;
}

// One test per property, named as the property, so that reproduce strings and corpus headers agree.
#define RAST_PROPERTY(name) \
    RC_GTEST_PROP(Properties, name, ()) { hold(#name, *scenes_for(#name), engines()); }

RAST_PROPERTY(watertight)
RAST_PROPERTY(tie_rule)
RAST_PROPERTY(winding_invariance)
RAST_PROPERTY(translation_invariance)
RAST_PROPERTY(order_independence)
RAST_PROPERTY(fixed_matches_reference)
RAST_PROPERTY(float_within_bound)
RAST_PROPERTY(msaa_counts)
RAST_PROPERTY(area_tiling)
RAST_PROPERTY(conforms)
RAST_PROPERTY(visible_area)
RAST_PROPERTY(msaa_visible_bound)
RAST_PROPERTY(lines_zbuffer)

// Every registered property has its test above.
TEST(Properties, EveryPropertyIsTested) {
    const std::vector<std::string> tested{"watertight", "tie_rule", "winding_invariance", "translation_invariance",
                                          "order_independence", "fixed_matches_reference", "float_within_bound",
                                          "msaa_counts", "area_tiling", "conforms", "visible_area",
                                          "msaa_visible_bound", "lines_zbuffer"};
    std::vector<std::string> registered;
    for (const auto& p : rast::properties::all_properties()) registered.emplace_back(p.name);
    EXPECT_EQ(registered, tested);
}

}  // namespace
