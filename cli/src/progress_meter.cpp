#include "progress_meter.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <utility>

namespace rast::cli {

namespace {
constexpr double kQuietSeconds = 2;      // a computation this short passes without a word
constexpr double kTerminalInterval = 0.25;
constexpr double kLogInterval = 10;
}  // namespace

ProgressMeter::ProgressMeter(std::string label, std::string unit, std::ostream& out, bool terminal, Clock clock)
    : label_(std::move(label)), unit_(std::move(unit)), out_(out), terminal_(terminal), clock_(std::move(clock)) {}

ProgressMeter::~ProgressMeter() {
    if (line_open_) out_ << '\n' << std::flush;
}

Progress ProgressMeter::progress() {
    return [this](std::size_t done, std::size_t total) { update(done, total); };
}

double ProgressMeter::steady_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void ProgressMeter::update(std::size_t done, std::size_t total) {
    const double now = clock_();
    if (done == 0) {
        start_ = now;
        spoken_ = false;
    }
    const bool last = done == total;
    if (last) {
        if (spoken_) show(done, total, now, true);
        return;
    }
    if (now - start_ < kQuietSeconds) return;
    if (spoken_ && now - shown_at_ < (terminal_ ? kTerminalInterval : kLogInterval)) return;
    show(done, total, now, false);
}

void ProgressMeter::show(std::size_t done, std::size_t total, double now, bool last) {
    char text[160];
    std::snprintf(text, sizeof text, "%s: %3zu%% (%zu of %zu %s), %.1f s", label_.c_str(), done * 100 / total,
                  done, total, unit_.c_str(), now - start_);
    // A terminal's line is rewritten in place (cleared to its end: the new text may be shorter).
    if (terminal_) out_ << '\r' << text << "\x1b[K";
    else out_ << text << '\n';
    line_open_ = terminal_ && !last;
    if (terminal_ && last) out_ << '\n';
    out_ << std::flush;
    spoken_ = true;
    shown_at_ = now;
}

std::unique_ptr<ProgressMeter> stderr_meter(std::string label, std::string unit) {
    return std::make_unique<ProgressMeter>(std::move(label), std::move(unit), std::cerr, isatty(STDERR_FILENO) == 1);
}

}  // namespace rast::cli
