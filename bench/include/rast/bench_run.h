// rast — `rast bench`: every engine and mode on the same scenes in one run, speed and error side by side.
#pragma once

#include <rast/bench_report.h>

#include <filesystem>
#include <iosfwd>
#include <string>

namespace rast::bench {

struct Config {
    bool quick = false;  // small scenes and few runs: under a minute, for CI smoke tests
    bool speed = true;   // speed and error of every engine on the main scenes
    bool hard = true;    // the hard-case families
    bool aa = true;      // the sample patterns against the exact area
    std::filesystem::path mesh;  // the real mesh; the Stanford bunny in meshes/bunny.off
    std::string command;         // as typed, recorded in the report
};

// Progress goes to `progress`, one line per measurement. Throws what the engines or the mesh reader throw.
Report run_bench(const Config& config, std::ostream& progress);

}  // namespace rast::bench
