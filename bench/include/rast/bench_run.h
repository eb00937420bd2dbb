// rast — `rast bench`: every engine and mode on the same scenes in one run, speed and error side by side.
#pragma once

#include <rast/bench_report.h>
#include <rast/engine.h>

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace rast::bench {

struct Config {
    bool quick = false;  // small scenes and few runs: under a minute, for CI smoke tests
    bool speed = true;   // speed and error of every engine on the main scenes
    bool hard = true;    // the hard-case families
    bool aa = true;      // the sample patterns against the exact area
    bool lines = true;   // line rasterizers: speed and pixels against the exact diamond-exit rule
    std::filesystem::path mesh;  // the real mesh; the Stanford bunny in meshes/bunny.off
    std::string command;         // as typed, recorded in the report
    // Plugins timed and compared beside rast's engines on the speed and hard-case scenes whose sample
    // count their contract renders (one thread as rast counts; ids only, so no coverage or depth columns).
    std::vector<Engine> plugins;
};

// Progress goes to `progress`, one line per measurement. Throws what the engines or the mesh reader throw.
Report run_bench(const Config& config, std::ostream& progress);

}  // namespace rast::bench
