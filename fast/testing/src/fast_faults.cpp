// The engine instantiated once per injected fault, for the property tests only.
#include "engine.h"

#include <rast/fast_faults.h>

namespace rast::fast {
namespace {

template <template <Fault> class Call, class... Args>
auto with_fault(Fault fault, Args&&... args) {
    switch (fault) {
        case Fault::none: return Call<Fault::none>::run(args...);
        case Fault::wrong_tie_bias: return Call<Fault::wrong_tie_bias>::run(args...);
        case Fault::integer_sample_positions: return Call<Fault::integer_sample_positions>::run(args...);
        case Fault::depth_less_equal: return Call<Fault::depth_less_equal>::run(args...);
        case Fault::no_id_tiebreak: return Call<Fault::no_id_tiebreak>::run(args...);
        case Fault::bbox_one_short: return Call<Fault::bbox_one_short>::run(args...);
        case Fault::float_row_accumulation: return Call<Fault::float_row_accumulation>::run(args...);
        case Fault::halved_depth_bound: return Call<Fault::halved_depth_bound>::run(args...);
        case Fault::halved_float_margin: return Call<Fault::halved_float_margin>::run(args...);
    }
    throw std::invalid_argument("rast::fast: unknown fault " + std::to_string(static_cast<int>(fault)));
}

template <Fault F>
struct Render {
    static Framebuffer run(const Scene& scene, const Options& options) {
        Framebuffer fb;
        detail::Workspace workspace;
        detail::render_scene<F>(scene, options, fb, workspace);
        return fb;
    }
};

template <Fault F>
struct Cover {
    static std::vector<std::size_t> run(const Triangle& t, Viewport vp, int samples, Precision precision) {
        return detail::covered_by<F>(t, vp, samples, precision);
    }
};

}  // namespace

Framebuffer render_with_fault(const Scene& scene, const Options& options, Fault fault) {
    return with_fault<Render>(fault, scene, options);
}

std::vector<std::size_t> covered_samples_with_fault(const Triangle& t, Viewport vp, int samples,
                                                    Precision precision, Fault fault) {
    return with_fault<Cover>(fault, t, vp, samples, precision);
}

}  // namespace rast::fast
