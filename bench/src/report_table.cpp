// The report as Markdown tables: what `rast bench` prints and what docs/bench.md shows.
#include <rast/bench_report.h>

#include <cstdio>
#include <map>
#include <string>

namespace rast::bench {
namespace {

std::string number(double value, const char* format = "%.3g") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

std::string count(const std::optional<std::uint64_t>& value) {
    return value ? std::to_string(*value) : "—";
}

std::string row(std::initializer_list<std::string> cells) {
    std::string line = "|";
    for (const std::string& cell : cells) line += " " + cell + " |";
    return line + "\n";
}

std::string scenes_table(const std::vector<SceneInfo>& scenes) {
    std::string out = row({"scene", "triangles", "viewport", "samples/pixel", "covered samples", "made by"}) +
                      row({"---", "---:", "---", "---:", "---:", "---"});
    for (const SceneInfo& s : scenes) {
        out += row({s.name, std::to_string(s.triangles),
                    std::to_string(s.viewport.width) + "×" + std::to_string(s.viewport.height),
                    std::to_string(s.samples), count(s.fragments), s.description});
    }
    return out;
}

std::string errors_table(const std::vector<ErrorRow>& errors, const char* scene_heading) {
    std::string out = row({scene_heading, "engine", "samples", "misclassified samples", "triangles affected",
                           "ids differing", "depths differing (bits)", "worst abs. Δz", "watertight violations"}) +
                      row({"---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
    for (const ErrorRow& e : errors) {
        out += row({e.scene, e.engine, std::to_string(e.samples), count(e.misclassified),
                    count(e.triangles_affected), std::to_string(e.ids_differing),
                    count(e.depths_differing), e.worst_depth_error ? number(*e.worst_depth_error, "%.2g") : "—",
                    count(e.watertight_violations)});
    }
    return out;
}

// Ratios from medians of the same run: against the reference, and against llvmpipe on as many threads.
std::string speed_table(const std::vector<SpeedRow>& speed) {
    std::map<std::string, double> reference, llvmpipe;
    for (const SpeedRow& s : speed) {
        if (s.engine == "reference") reference[s.scene] = s.median;
        if (s.engine == "llvmpipe") llvmpipe[s.scene + "/" + std::to_string(s.threads)] = s.median;
    }
    const auto ratio = [](const std::map<std::string, double>& base, const std::string& key, double median) {
        const auto it = base.find(key);
        return it == base.end() ? std::string("—") : number(it->second / median) + "×";
    };
    std::string out = row({"scene", "engine", "threads", "runs", "median ms", "min–max ms", "M triangles/s",
                           "M samples/s", "vs reference", "vs llvmpipe"}) +
                      row({"---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
    for (const SpeedRow& s : speed) {
        out += row({s.scene, s.engine, std::to_string(s.threads), std::to_string(s.runs),
                    number(s.median * 1e3), number(s.min * 1e3) + "–" + number(s.max * 1e3),
                    number(s.triangles_per_second / 1e6), number(s.samples_per_second / 1e6),
                    ratio(reference, s.scene, s.median),
                    ratio(llvmpipe, s.scene + "/" + std::to_string(s.threads), s.median)});
    }
    return out;
}

std::string aa_tables(const Report& report) {
    std::string out = row({"scene", "samples/pixel", "pixels", "mean abs. error", "worst abs. error"}) +
                      row({"---", "---:", "---:", "---:", "---:"});
    for (const AaRow& a : report.aa) {
        out += row({a.scene, std::to_string(a.error.samples), std::to_string(a.error.pixels),
                    number(a.error.mean, "%.4f"), number(a.error.worst, "%.4f")});
    }
    out += '\n';
    out += row({"samples/pixel", "halfplane discrepancy", "worst half-plane (n · p ≤ c)", "resolution"});
    out += row({"---:", "---:", "---", "---:"});
    for (const auto& [n, d] : report.discrepancy) {
        out += row({std::to_string(n), number(d.value, "%.5f"),
                    "n = (" + number(d.normal_x, "%.4g") + ", " + number(d.normal_y, "%.4g") + "), c = " +
                        number(d.offset, "%.4g"),
                    number(d.resolution, "%.1e")});
    }
    return out;
}

// Beside each visible-area row, the depth-ignoring figures of the same scene and pattern, where measured.
std::string visible_tables(const Report& report) {
    std::map<std::pair<std::string, int>, PatternError> ignoring;
    for (const AaRow& a : report.aa) ignoring[{a.scene, a.error.samples}] = a.error;
    std::string out = row({"scene", "samples/pixel", "pixels", "mean error", "worst error",
                           "depth ignored: mean / worst"}) +
                      row({"---", "---:", "---:", "---:", "---:", "---:"});
    for (const VisibleAaRow& v : report.visible_aa) {
        const auto it = ignoring.find({v.scene, v.error.samples});
        out += row({v.scene, std::to_string(v.error.samples), std::to_string(v.error.pixels),
                    number(v.error.mean, "%.4f"), number(v.error.worst, "%.4f"),
                    it == ignoring.end() ? "—"
                                         : number(it->second.mean, "%.4f") + " / " + number(it->second.worst, "%.4f")});
    }
    out += "\nThe cost of the exact visible area (one run; exact, so every run gives the same areas):\n\n";
    out += row({"scene", "triangles", "viewport", "pixels cut", "triangles per pixel cut", "threads", "seconds",
                "µs per pixel cut"}) +
           row({"---", "---:", "---", "---:", "---:", "---:", "---:", "---:"});
    for (const VisibleCostRow& c : report.visible_cost) {
        const double pixels = static_cast<double>(c.stats.pixels_cut);
        out += row({c.scene, std::to_string(c.triangles),
                    std::to_string(c.viewport.width) + "×" + std::to_string(c.viewport.height),
                    std::to_string(c.stats.pixels_cut),
                    pixels == 0 ? "—" : number(static_cast<double>(c.stats.candidates) / pixels, "%.2f"),
                    std::to_string(c.threads), number(c.seconds, "%.2f"),
                    pixels == 0 ? "—" : number(c.seconds * 1e6 / pixels, "%.1f")});
    }
    return out;
}

std::string lines_table(const std::vector<LineRow>& lines) {
    std::map<std::string, double> reference;
    for (const LineRow& l : lines)
        if (l.engine == "reference") reference[l.scene] = l.median;
    std::string out = row({"scene", "engine", "segments", "median ms", "min–max ms", "M lines/s", "vs reference",
                           "pixels lit (reference)", "pixels differing", "segments affected"}) +
                      row({"---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
    for (const LineRow& l : lines) {
        const auto it = reference.find(l.scene);
        out += row({l.scene, l.engine, std::to_string(l.segments), number(l.median * 1e3),
                    number(l.min * 1e3) + "–" + number(l.max * 1e3),
                    number(static_cast<double>(l.segments) / l.median / 1e6),
                    it == reference.end() ? "—" : number(it->second / l.median) + "×", std::to_string(l.pixels),
                    std::to_string(l.differing), std::to_string(l.segments_affected)});
    }
    return out;
}

}  // namespace

std::string format_table(const Report& report) {
    const Machine& m = report.machine;
    std::string out = "Machine: " + m.cpu + ", " + std::to_string(m.cores) + " cores, load average " +
                      number(m.load_before, "%.2f") + " at the start and " + number(m.load_after, "%.2f") +
                      " at the end; " + m.date + (report.quick ? "; --quick" : "") + "\n";
    if (!report.command.empty()) out += "Command: `" + report.command + "`\n";
    if (!report.scenes.empty()) {
        out += "\n### Scenes\n\n" + scenes_table(report.scenes);
        out += "\n### Speed\n\n"
               "Wall time per render, median and range over the rounds. Samples/s\n"
               "counts the samples covered before the depth test. Ratios divide medians of this run: the\n"
               "reference's (one thread), and llvmpipe's on as many threads.\n\n" +
               speed_table(report.speed);
        out += "\n### Error against the exact reference\n\n"
               "Misclassified: samples covered by a mode or by the reference but not both, triangle by\n"
               "triangle (llvmpipe offers only its framebuffer). Ids and depths: framebuffer samples that differ\n"
               "(llvmpipe's depth buffer is 24-bit). Watertight violations, on meshes: samples whose winding\n"
               "count differs from the exact one of the geometry the mode rasterizes (cracks, double covers).\n\n" +
               errors_table(report.errors, "scene");
    }
    if (!report.hard_cases.empty()) {
        out += "\n### Hard cases\n\n" + scenes_table(report.hard_families) + "\n" +
               errors_table(report.hard_cases, "family");
    }
    if (!report.aa.empty()) {
        out += "\n### Antialiasing: sample patterns against the exact area\n\n" + scenes_table(report.aa_scenes) +
               "\n" + aa_tables(report);
    }
    if (!report.visible_aa.empty() || !report.visible_cost.empty()) {
        out += "\n### Antialiasing with depth: the resolved image against the exact visible area\n\n"
               "Per pixel, the total variation between the fractions of the samples (reference, z-buffered)\n"
               "each triangle holds and the areas it sees: the largest error of the resolved colour, colours\n"
               "in [0, 1]. Pixels where something is seen or covered. Beside it, the depth-ignoring error of\n"
               "each triangle's own area (the table above), which misses what occlusion does.\n\n" +
               visible_tables(report);
    }
    if (!report.lines.empty()) {
        out += "\n### Lines\n\n"
               "Each engine over every segment of a set, one thread; pixels against the exact diamond-exit rule\n"
               "on the same segments (Bresenham snaps the ends to 1/256 pixel first, and equals the reference on\n"
               "the snapped segment; what differs here is the snapping).\n\n" +
               lines_table(report.lines);
    }
    for (const std::string& note : report.notes) out += "\nNote: " + note + "\n";
    return out;
}

}  // namespace rast::bench
