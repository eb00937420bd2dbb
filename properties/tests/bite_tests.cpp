// Each property bites: run on a deliberately broken fast path with a fixed seed, it fails, and its
// counterexample is kept. If a property or a generator loses its power, one of these tests fails.
#include <rast/exact_geometry.h>
#include <rast/fast_faults.h>
#include <rast/tri_format.h>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <set>
#include <stdexcept>

#include "checks.h"
#include "property_harness.h"

namespace {

using rast::Framebuffer;
using rast::Scene;
using rast::Triangle;
using rast::Viewport;
using rast::fast::Fault;
using rast::fast::Precision;
using rast::Engine;

// Broken variants written here, for the properties that no fault inside the fast path breaks: the
// wrapper changes what the fast path is given, as a careless caller or setup stage would.
enum class Wrapper {
    none,
    culling_left_on,     // clockwise triangles dropped: back-face culling where none was asked for
    snap_by_truncation,  // vertices cut toward zero to 1/256 before the fixed8 path, not rounded
    throws_on_overlap,   // an exception (as from a failed allocation or check) where two triangles overlap
    lines_last,          // lines ordered after every triangle, not in file order, ids then given back
};

struct Bite {
    const char* name;  // for the test's name
    Fault fault;
    Wrapper wrapper;
    Precision precision;
    const char* property;
};

// Test names and messages show a bite by its name.
void PrintTo(const Bite& b, std::ostream* os) { *os << b.name; }

Triangle cut_toward_zero(Triangle t) {
    for (auto& v : t.v) {
        v.x = std::ldexp(std::trunc(std::ldexp(v.x, 8)), -8);
        v.y = std::ldexp(std::trunc(std::ldexp(v.y, 8)), -8);
    }
    return t;
}

Triangle culled(const Triangle& t) {
    if (rast::properties::orientation(t) >= 0) return t;
    return {{t.v[0], t.v[0], t.v[0]}};  // zero area: covers nothing, keeps its id
}

// Whether some sample is covered by two triangles (by the reference's coverage).
bool has_overlap(const Scene& s) {
    const Engine reference = rast::reference_engine();
    std::set<std::size_t> seen;
    for (const Triangle& t : s.triangles)
        for (const std::size_t sample : reference.covered_samples(t, s.viewport, s.samples))
            if (!seen.insert(sample).second) return true;
    return false;
}

Engine broken(const Bite& b) {
    Engine e = rast::fast_engine(b.precision);
    const auto given = [w = b.wrapper](const Triangle& t) {
        return w == Wrapper::culling_left_on ? culled(t) : w == Wrapper::snap_by_truncation ? cut_toward_zero(t) : t;
    };
    e.draw = [b, given](const Scene& s, Framebuffer& fb) {
        if (b.wrapper == Wrapper::throws_on_overlap && has_overlap(s))
            throw std::runtime_error("the engine gave up on overlapping triangles");
        Scene seen = s;
        for (Triangle& t : seen.triangles) t = given(t);
        if (b.wrapper == Wrapper::lines_last) {
            // Drawn with the triangles first, then named back: their (z, id) ties go the wrong way.
            const std::vector<std::int32_t> ids = rast::triangle_ids(s);
            std::vector<std::int32_t> back = ids;
            for (std::size_t k = 0; k < s.lines.size(); ++k) {
                seen.lines[k].id = static_cast<std::int32_t>(s.triangles.size() + k);
                back.push_back(s.lines[k].id);
            }
            fb = rast::fast::render_with_fault(seen, {b.precision, 1}, b.fault);
            for (std::int32_t& id : fb.ids)
                if (id != Framebuffer::kNoTriangle) id = back[static_cast<std::size_t>(id)];
            return;
        }
        fb = rast::fast::render_with_fault(seen, {b.precision, 1}, b.fault);
    };
    e.covered_samples = [b, given](const Triangle& t, Viewport vp, int n) {
        return rast::fast::covered_samples_with_fault(given(t), vp, n, b.precision, b.fault);
    };
    return e;
}

class Bites : public ::testing::TestWithParam<Bite> {
protected:
    void SetUp() override {
        corpus_ = std::filesystem::temp_directory_path() /
                  ("rast-bite-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                   GetParam().name);
        std::filesystem::remove_all(corpus_);
        ::setenv("RAST_CORPUS_OUT", corpus_.c_str(), 1);
    }
    void TearDown() override {
        ::unsetenv("RAST_CORPUS_OUT");
        std::filesystem::remove_all(corpus_);
    }
    std::filesystem::path corpus_;
};

// The search every bite runs, 300 cases from a fixed seed (the test is about this search, not a lucky
// one); whether it failed.
template <class Testable>
bool search_fails(const std::string& id, Testable testable) {
    rc::detail::TestMetadata metadata;
    metadata.id = id;
    rc::detail::TestParams params;
    params.seed = 20261121;
    params.maxSuccess = 300;
    return rc::detail::checkTestable(testable, metadata, params).template is<rc::detail::FailureResult>();
}

TEST_P(Bites, PropertyFailsAndKeepsItsCounterexample) {
    const Bite& b = GetParam();
    const std::vector<Engine> engine{broken(b)};
    ASSERT_TRUE(search_fails(std::string("Bites/") + b.name,
                             [&] { rast::harness::hold(b.property, *rast::gen::scenes_for(b.property), engine); }))
        << b.property << " did not detect " << b.name;

    // The minimal counterexample was kept where RAST_CORPUS_OUT says, naming the property it breaks.
    ASSERT_TRUE(std::filesystem::is_directory(corpus_));
    std::vector<std::filesystem::path> kept(std::filesystem::directory_iterator(corpus_), {});
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0].filename().string().rfind(std::string(b.property) + "-", 0), 0u);
    const auto document = rast::read_tri_document_file(kept[0]);
    EXPECT_EQ(document.header.at(0), (std::pair<std::string, std::string>{"properties", b.property}));
    // Replayed on the broken engine, the kept scene still fails the property.
    const auto& p = rast::properties::property(b.property);
    EXPECT_TRUE(p.verdict_on(document.scene, engine[0]).failed());
}

// For each fault, the properties that must notice it.
const Bite kBites[] = {
    {"wrong_tie_bias_tie_rule", Fault::wrong_tie_bias, Wrapper::none, Precision::fixed8, "tie_rule"},
    {"wrong_tie_bias_msaa_counts", Fault::wrong_tie_bias, Wrapper::none, Precision::fixed4, "msaa_counts"},
    {"wrong_tie_bias_fixed_matches_reference", Fault::wrong_tie_bias, Wrapper::none, Precision::fixed16,
     "fixed_matches_reference"},
    {"integer_samples_watertight", Fault::integer_sample_positions, Wrapper::none, Precision::fixed8, "watertight"},
    {"integer_samples_tie_rule", Fault::integer_sample_positions, Wrapper::none, Precision::fixed4, "tie_rule"},
    {"integer_samples_area_tiling", Fault::integer_sample_positions, Wrapper::none, Precision::fixed8, "area_tiling"},
    {"integer_samples_msaa_counts", Fault::integer_sample_positions, Wrapper::none, Precision::fixed16,
     "msaa_counts"},
    {"integer_samples_float_within_bound", Fault::integer_sample_positions, Wrapper::none, Precision::float32,
     "float_within_bound"},
    {"depth_less_equal_order_independence", Fault::depth_less_equal, Wrapper::none, Precision::fixed8,
     "order_independence"},
    {"depth_less_equal_order_independence_float64", Fault::depth_less_equal, Wrapper::none, Precision::float64,
     "order_independence"},
    {"depth_less_equal_fixed_matches_reference", Fault::depth_less_equal, Wrapper::none, Precision::fixed8,
     "fixed_matches_reference"},
    {"no_id_tiebreak_order_independence", Fault::no_id_tiebreak, Wrapper::none, Precision::fixed16,
     "order_independence"},
    {"no_id_tiebreak_order_independence_float32", Fault::no_id_tiebreak, Wrapper::none, Precision::float32,
     "order_independence"},
    {"no_id_tiebreak_fixed_matches_reference", Fault::no_id_tiebreak, Wrapper::none, Precision::fixed8,
     "fixed_matches_reference"},
    {"bbox_one_short_watertight", Fault::bbox_one_short, Wrapper::none, Precision::fixed8, "watertight"},
    {"bbox_one_short_tie_rule", Fault::bbox_one_short, Wrapper::none, Precision::fixed16, "tie_rule"},
    {"bbox_one_short_area_tiling", Fault::bbox_one_short, Wrapper::none, Precision::fixed4, "area_tiling"},
    {"bbox_one_short_msaa_counts", Fault::bbox_one_short, Wrapper::none, Precision::fixed8, "msaa_counts"},
    {"bbox_one_short_fixed_matches_reference", Fault::bbox_one_short, Wrapper::none, Precision::fixed8,
     "fixed_matches_reference"},
    {"float_row_accumulation_float_within_bound", Fault::float_row_accumulation, Wrapper::none, Precision::float64,
     "float_within_bound"},
    {"bbox_one_short_float_within_bound", Fault::bbox_one_short, Wrapper::none, Precision::float64,
     "float_within_bound"},
    {"culling_left_on_winding_invariance", Fault::none, Wrapper::culling_left_on, Precision::fixed8,
     "winding_invariance"},
    {"snap_by_truncation_translation_invariance", Fault::none, Wrapper::snap_by_truncation, Precision::fixed8,
     "translation_invariance"},
    {"throws_on_overlap_order_independence", Fault::none, Wrapper::throws_on_overlap, Precision::fixed8,
     "order_independence"},
    {"depth_less_equal_conforms", Fault::depth_less_equal, Wrapper::none, Precision::fixed8, "conforms"},
    {"bbox_one_short_conforms", Fault::bbox_one_short, Wrapper::none, Precision::fixed16, "conforms"},
    {"snap_by_truncation_conforms", Fault::none, Wrapper::snap_by_truncation, Precision::fixed8, "conforms"},
    {"no_id_tiebreak_msaa_visible_bound", Fault::no_id_tiebreak, Wrapper::none, Precision::fixed8,
     "msaa_visible_bound"},
    {"bbox_one_short_msaa_visible_bound", Fault::bbox_one_short, Wrapper::none, Precision::fixed16,
     "msaa_visible_bound"},
    {"lines_last_lines_zbuffer", Fault::none, Wrapper::lines_last, Precision::fixed8, "lines_zbuffer"},
};

INSTANTIATE_TEST_SUITE_P(Faults, Bites, ::testing::ValuesIn(kBites),
                         [](const ::testing::TestParamInfo<Bite>& info) { return std::string(info.param.name); });

// A careless visible area: coplanar overlaps go to the higher id (the scene reversed, ids mapped back).
rast::reference::VisibleArea ties_to_the_higher_id(const Scene& s) {
    Scene reversed = s;
    std::reverse(reversed.triangles.begin(), reversed.triangles.end());
    const auto visible = rast::reference::visible_area(reversed);
    const std::size_t last = s.triangles.size() - 1;
    std::vector<std::size_t> first{0};
    std::vector<rast::reference::VisiblePiece> pieces;
    for (int j = 0; j < s.viewport.height; ++j)
        for (int i = 0; i < s.viewport.width; ++i) {
            const auto at = visible.at(i, j);
            for (auto p = at.rbegin(); p != at.rend(); ++p) pieces.push_back({last - p->id, p->area});
            first.push_back(pieces.size());
        }
    return {s.viewport, std::move(first), std::move(pieces)};
}

// visible_area judges the reference's own visible area, not an engine: it bites a broken one.
TEST(Bites, VisibleAreaCatchesTiesToTheHigherId) {
    EXPECT_TRUE(search_fails("Bites/visible_area_ties_to_the_higher_id", [] {
        const Scene scene = *rast::gen::scenes_for("visible_area");
        RC_ASSERT(!rast::properties::visible_area_of(scene, ties_to_the_higher_id).failed());
    }));
}

// Every property is bitten by at least one broken variant above.
TEST(Bites, EveryPropertyIsBitten) {
    for (const auto& p : rast::properties::all_properties()) {
        bool bitten = p.name == "visible_area";  // by the test above
        for (const Bite& b : kBites) bitten = bitten || p.name == b.property;
        EXPECT_TRUE(bitten) << p.name;
    }
}

}  // namespace
