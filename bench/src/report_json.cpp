// The report as JSON: every measured number, nothing derived but the rates.
#include <rast/bench_report.h>

#include <nlohmann/json.hpp>

namespace rast::bench {
namespace {

using nlohmann::json;

json optional_count(const std::optional<std::uint64_t>& value) { return value ? json(*value) : json(nullptr); }

json scenes_json(const std::vector<SceneInfo>& scenes) {
    json out = json::array();
    for (const SceneInfo& s : scenes) {
        out.push_back({{"name", s.name}, {"description", s.description}, {"triangles", s.triangles},
                       {"width", s.viewport.width}, {"height", s.viewport.height}, {"samples", s.samples},
                       {"covered_samples", optional_count(s.fragments)}});
    }
    return out;
}

json errors_json(const std::vector<ErrorRow>& errors) {
    json out = json::array();
    for (const ErrorRow& e : errors) {
        out.push_back({{"scene", e.scene}, {"engine", e.engine}, {"samples", e.samples},
                       {"misclassified_samples", optional_count(e.misclassified)},
                       {"triangles_affected", optional_count(e.triangles_affected)},
                       {"ids_differing", e.ids_differing}, {"depths_differing", optional_count(e.depths_differing)},
                       {"worst_depth_error", e.worst_depth_error ? json(*e.worst_depth_error) : json(nullptr)},
                       {"watertight_violations", optional_count(e.watertight_violations)}});
    }
    return out;
}

}  // namespace

std::string format_json(const Report& report) {
    json speed = json::array();
    for (const SpeedRow& s : report.speed) {
        speed.push_back({{"scene", s.scene}, {"engine", s.engine}, {"threads", s.threads}, {"runs", s.runs},
                         {"median_s", s.median}, {"min_s", s.min}, {"max_s", s.max},
                         {"triangles_per_s", s.triangles_per_second}, {"samples_per_s", s.samples_per_second}});
    }
    json aa = json::array();
    for (const AaRow& a : report.aa) {
        aa.push_back({{"scene", a.scene}, {"samples", a.error.samples}, {"pixels", a.error.pixels},
                      {"mean_error", a.error.mean}, {"worst_error", a.error.worst}});
    }
    json discrepancy = json::array();
    for (const auto& [n, d] : report.discrepancy) {
        discrepancy.push_back({{"samples", n}, {"halfplane_discrepancy", d.value},
                               {"normal", {d.normal_x, d.normal_y}}, {"offset", d.offset},
                               {"resolution_rad", d.resolution}});
    }
    json visible = json::array();
    for (const VisibleAaRow& v : report.visible_aa) {
        visible.push_back({{"scene", v.scene}, {"samples", v.error.samples}, {"pixels", v.error.pixels},
                           {"mean_error", v.error.mean}, {"worst_error", v.error.worst}});
    }
    json cost = json::array();
    for (const VisibleCostRow& c : report.visible_cost) {
        cost.push_back({{"scene", c.scene}, {"triangles", c.triangles},
                        {"viewport", {c.viewport.width, c.viewport.height}}, {"pixels_cut", c.stats.pixels_cut},
                        {"candidates", c.stats.candidates}, {"threads", c.threads}, {"seconds", c.seconds}});
    }
    json lines = json::array();
    for (const LineRow& l : report.lines) {
        lines.push_back({{"scene", l.scene}, {"engine", l.engine}, {"segments", l.segments}, {"median_s", l.median},
                         {"min_s", l.min}, {"max_s", l.max}, {"runs", l.runs}, {"pixels", l.pixels},
                         {"pixels_differing", l.differing}, {"segments_affected", l.segments_affected}});
    }
    const Machine& m = report.machine;
    const json out = {
        {"machine", {{"cpu", m.cpu}, {"cores", m.cores}, {"load_before", m.load_before},
                     {"load_after", m.load_after}, {"date", m.date}}},
        {"command", report.command},
        {"quick", report.quick},
        {"scenes", scenes_json(report.scenes)},
        {"speed", speed},
        {"errors", errors_json(report.errors)},
        {"hard_case_families", scenes_json(report.hard_families)},
        {"hard_cases", errors_json(report.hard_cases)},
        {"antialiasing_scenes", scenes_json(report.aa_scenes)},
        {"antialiasing", aa},
        {"halfplane_discrepancy", discrepancy},
        {"visible_antialiasing", visible},
        {"visible_area_cost", cost},
        {"lines", lines},
        {"notes", report.notes},
    };
    return out.dump(2) + "\n";
}

}  // namespace rast::bench
