#include "conform_reports.h"

#include <rast/conformance.h>
#include <rast/exact_geometry.h>
#include <rast/reference.h>

#include <nlohmann/json.hpp>

#include <algorithm>

#include "png_image.h"
#include "wording.h"

namespace rast::cli {

namespace {

const char* verdict_status(const conform::PropertyVerdict& p) {
    return p.failure ? "FAIL" : p.checked == 0 ? "SKIP" : "PASS";
}

// Markdown table cells hold no '|' and no line break.
std::string cell(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::string out;
    for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

// The scene the reference draws for comparison: the contract's one snapping where it has one.
Scene as_snapped(const Scene& scene, const std::optional<Contract>& contract) {
    if (!contract || !contract->snap || contract->rounding == Contract::Rounding::any) return scene;
    Scene out = scene;
    for (Triangle& t : out.triangles) t = properties::snap(t, *contract->snap, contract->rounding);
    return out;
}

Image demands_image(const Scene& scene, const std::vector<properties::Demand>& demands) {
    const Viewport vp = scene.viewport;
    Image out(vp.width, vp.height);
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            int sum = 0;
            for (int s = 0; s < scene.samples; ++s) {
                const std::size_t k = (static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width) +
                                       static_cast<std::size_t>(i)) * static_cast<std::size_t>(scene.samples) +
                                      static_cast<std::size_t>(s);
                sum += demands[k] == properties::Demand::required ? 255 : demands[k] == properties::Demand::free ? 128 : 0;
            }
            std::uint8_t* px = out.at(i, vp.height - 1 - j);
            px[0] = px[1] = px[2] = static_cast<std::uint8_t>(sum / scene.samples);
        }
    return out;
}

}  // namespace

std::string conform_json(const ConformRun& run, const conform::Verdict& verdict) {
    nlohmann::json properties = nlohmann::json::array();
    std::size_t failed = 0, skipped = 0;
    for (const auto& p : verdict.properties) {
        skipped += !p.failure && p.checked == 0;
        nlohmann::json entry{{"property", p.property},
                             {"status", verdict_status(p)},
                             {"scenes_checked", p.checked},
                             {"not_applicable", p.not_applicable}};
        if (p.failure) {
            ++failed;
            entry["failure"] = {{"detail", p.failure->detail},
                                {"origin", p.failure->origin},
                                {"triangles", p.failure->scene.triangles.size()},
                                {"original_triangles", p.failure->original_triangles},
                                {"case", p.failure->kept.string()}};
        }
        properties.push_back(std::move(entry));
    }
    const nlohmann::json report{{"engine", verdict.engine},
                                {"library", run.library},
                                {"contract", verdict.contract ? verdict.contract->text() : ""},
                                {"battery", run.battery},
                                {"conforms", verdict.conforms()},
                                {"passed", verdict.properties.size() - failed - skipped},
                                {"failed", failed},
                                {"skipped", skipped},
                                {"properties", properties}};
    return report.dump(2) + "\n";
}

std::string conform_markdown(const ConformRun& run, const conform::Verdict& verdict) {
    std::string out = "# rast conform: " + verdict.engine + "\n\n";
    out += "- library: `" + run.library + "`\n";
    out += "- contract: `" + (verdict.contract ? verdict.contract->text() : std::string("none")) + "`\n";
    out += "- " + run.battery + "\n";
    out += std::string("- verdict: ") + (verdict.conforms() ? "conforms" : "does not conform") + "\n\n";
    out += "| property | verdict | scenes | first violation | shrunk case |\n|---|---|---|---|---|\n";
    for (const auto& p : verdict.properties) {
        out += "| " + p.property + " | " + verdict_status(p) + " | " + std::to_string(p.checked) + " | ";
        if (p.failure)
            out += cell(p.failure->detail) + " | " +
                   counted(p.failure->scene.triangles.size(), "triangle", "triangles") + " (from " +
                   std::to_string(p.failure->original_triangles) + ", " +
                   cell(p.failure->origin) + ")" + (p.failure->kept.empty() ? "" : ": `" + p.failure->kept.string() + "`");
        else
            out += " | ";
        out += " |\n";
    }
    return out;
}

std::string counterexample_png(const Engine& engine, const conform::Finding& finding) {
    const Scene& scene = finding.scene;
    const Contract contract = engine.contract.value_or(Contract{});
    const Image demands = demands_image(scene, properties::coverage_demands(scene, contract));
    const Image engines = resolve_ids(engine.render(scene));
    const Image exact = resolve_ids(reference::render(as_snapped(scene, engine.contract)));
    const int side = std::max(scene.viewport.width, scene.viewport.height);
    const int scale = std::clamp(256 / side, 1, 64);
    return encode_png(side_by_side({demands, engines, exact}, scale));
}

}  // namespace rast::cli
