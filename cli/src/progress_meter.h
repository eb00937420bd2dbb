// rast — a word on stderr while a long computation runs, so that a slow exact render is not mistaken for
// a hang.
#pragma once

#include <rast/progress.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace rast::cli {

// Says nothing for a computation that ends within two seconds. After that it shows how far it has come: on
// a terminal one line rewritten at most four times a second, elsewhere (a log) a line every ten seconds;
// and, once it has spoken, a last line with the time taken. A computation begins at its Progress call
// with done == 0, so one meter serves several in turn.
class ProgressMeter {
public:
    using Clock = std::function<double()>;  // seconds, from any fixed origin, never decreasing

    // label: what runs ("reference render"); unit: what `done` counts ("triangles").
    ProgressMeter(std::string label, std::string unit, std::ostream& out, bool terminal,
                  Clock clock = steady_seconds);
    // Ends a rewritten line left open by a computation that did not finish (an exception).
    ~ProgressMeter();
    ProgressMeter(const ProgressMeter&) = delete;
    ProgressMeter& operator=(const ProgressMeter&) = delete;

    // A Progress that reports here; the meter must outlive it.
    Progress progress();
    void update(std::size_t done, std::size_t total);

    static double steady_seconds();

private:
    void show(std::size_t done, std::size_t total, double now, bool last);

    std::string label_, unit_;
    std::ostream& out_;
    bool terminal_;
    Clock clock_;
    double start_ = 0, shown_at_ = 0;
    bool spoken_ = false, line_open_ = false;
};

// A meter on this process's stderr, rewriting its line when stderr is a terminal.
std::unique_ptr<ProgressMeter> stderr_meter(std::string label, std::string unit);

}  // namespace rast::cli
